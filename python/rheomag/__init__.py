"""rheomag: finite-element design of magnetorheological valves, dampers and brakes.

SI units throughout (m, A, T, Pa, m^3/s, s, J, H). See docs/python.md.
"""

from ._rheomag import (  # noqa: F401  (the public API)
    Case,
    ConvergenceError,
    Gap,
    Mesh,
    Recording,
    Solution,
    __version__,
    diagnose,
    fit,
    fit_family,
    simulate,
)
