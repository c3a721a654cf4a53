00001 StartSession()
\\
E0005 OnMoveReportE(Time(1), X(), Y(), Z())
\\
00002 Home()
\\
00003 GetProp(Tool.PtMeasPar.Speed())
\\
00004 SetCsyTransformation(PartCsy, 5, 6, 7, 10, 20, 30)
\\
00005 SetCoordSystem(PartCsy)
\\
00006 ChangeTool("Probe1")
\\
00007 OnPtMeasReport(X(), Y(), Z(), IJK(), ER())
\\
00008 PtMeas(X(1.33), IJK(0, 0, 1.0), Y(-2.6E01), Z(30.998))
\\
00009 ScanOnLine(1,2,3,4,5,6,7,8,9,10)
\\
00010 EndSession()
\\
:
:
