"""SPH kernels in NumPy, the same functions as upf's C++ kernels, for solvers written in Python.

cubic_spline: Monaghan 1992 ("Smoothed particle hydrodynamics", Annu. Rev. Astron. Astrophys.
30), written with the support radius H (= 2h) as in SPlisHSPlasH and framework/kernels/
cubic_spline.h: q = r / H, W = k (6q^3 - 6q^2 + 1) for q <= 1/2, W = 2k (1 - q)^3 for q <= 1,
k = 8 / (pi H^3).
"""

import numpy as np


def cubic_spline(r, support_radius):
    """W(r) for distances r (any shape)."""
    h = float(support_radius)
    q = np.asarray(r, dtype=np.float64) / h
    k = 8.0 / (np.pi * h ** 3)
    inner = k * (6.0 * q ** 3 - 6.0 * q ** 2 + 1.0)
    outer = 2.0 * k * (1.0 - q) ** 3
    return np.where(q <= 0.5, inner, np.where(q < 1.0, outer, 0.0))


def cubic_spline_gradient(dx, support_radius):
    """grad W with respect to x_i for offsets dx = x_i - x_j, shape (n, 3)."""
    h = float(support_radius)
    dx = np.asarray(dx, dtype=np.float64)
    r = np.linalg.norm(dx, axis=1)
    q = r / h
    l = 48.0 / (np.pi * h ** 3)
    slope = np.where(q <= 0.5, l * q * (3.0 * q - 2.0), -l * (1.0 - q) ** 2)
    slope = np.where((q < 1.0) & (r > 1e-9 * h), slope, 0.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        scale = np.where(r > 1e-9 * h, slope / (r * h), 0.0)
    return dx * scale[:, None]
