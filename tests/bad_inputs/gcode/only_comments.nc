(nothing)
; nothing
%
