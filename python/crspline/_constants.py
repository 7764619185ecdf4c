"""The named constants of crspline: the three alphas, the default accuracy
and the largest dimension the compiled module takes."""
from . import _crspline

#: alpha = 0: every knot interval is 1.
uniform = 0.0
#: alpha = 1/2: the default of CatmullRom; no cusps or loops within a segment.
centripetal = 0.5
#: alpha = 1: knot intervals equal to the chord lengths.
chordal = 1.0
#: Default relative accuracy of arc lengths (1e-12).
default_accuracy = float(_crspline.default_accuracy)
#: Largest dimension compiled into the module.
max_dimension = int(_crspline.max_dimension)
