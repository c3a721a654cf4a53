00001 StartSession()
\\
00002 Home()
\\
00003 SetCoordSystem(PartCsy)
\\
00004 ChangeTool("Probe1")
\\
00005 SetProp(Tool.PtMeasPar.Approach(3.000000))
\\
00006 SetProp(Tool.PtMeasPar.Retract(3.000000))
\\
00007 SetProp(Tool.PtMeasPar.Search(3.000000))
\\
00008 SetProp(Tool.GoToPar.Speed(50.000000))
\\
00009 SetProp(Tool.PtMeasPar.Speed(4.000000))
\\
00010 OnPtMeasReport(X(), Y(), Z(), IJK())
\\
00011 GoTo(X(5.000000), Y(5.000000), Z(9.000000))
\\
00012 PtMeas(X(5.000000), Y(5.000000), Z(5.000000), IJK(0.000000000, 0.000000000, 1.000000000))
\\
00013 GoTo(X(15.000000), Y(5.000000), Z(9.000000))
\\
00014 PtMeas(X(15.000000), Y(5.000000), Z(5.000000), IJK(0.000000000, 0.000000000, 1.000000000))
\\
00015 GoTo(X(15.000000), Y(5.000000), Z(12.000000))
\\
00016 GoTo(X(10.000000), Y(17.400000), Z(12.000000))
\\
00017 GoTo(X(10.000000), Y(17.400000), Z(8.200000))
\\
00018 PtMeas(X(10.000000), Y(15.000000), Z(5.000000), IJK(0.000000000, 0.600000000, 0.800000000))
\\
00019 GoTo(X(10.000000), Y(17.400000), Z(12.000000))
\\
00020 EndSession()
\\
:
:
