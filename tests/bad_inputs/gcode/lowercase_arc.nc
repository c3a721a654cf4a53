%
o1000 (cam output)
n10 g21 g90 g17
n20 g0 x0 y0 z30
n30 g2 x10 y10 i5 j0 f800
N50 G0 Z30
N60 M30
%
