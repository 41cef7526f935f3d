"""Laplace's pressure jump and Rayleigh's n = 2 oscillation of free drops without gravity, for
issue 41's surface tension models (docs/surface-tension.md, "What does not hold yet").

laplace: the mean pressure within R / 2 of a resting drop's centre, less the mean pressure within
a quarter of the thickness of a flat slab's mid-plane (periodic in x and z): the jump a curved face
adds over a flat one, against Laplace's 2 sigma / R. A cohesive model's bulk pressure is the same
under both faces, so it cancels.

rayleigh: a drop started in its n = 2 mode by the mode's potential flow (v = a (-x, -y, 2z),
amplitude --amplitude of R); prints the times at which the deformation <z^2> - (<x^2> + <y^2>) / 2
crosses its mean, against Rayleigh's period 2 pi / sqrt(8 sigma / (rho0 R^3)).

    PYTHONPATH=build/release/python /usr/bin/python3 bench/surface_tension_drops.py laplace \
        [--radii 8 12] [--viscosity 1e-4] [--dt 4e-4] [--model akinci2013] [--prototype-csf]
    PYTHONPATH=build/release/python /usr/bin/python3 bench/surface_tension_drops.py rayleigh \
        [--radii 8] [--viscosity 1e-5] [--end 1.5]

--model csf measures the registered continuum surface force. --prototype-csf replaces the model by
a Python force (needs python3-scipy): the continuum surface force with the curvature of a quadric
fitted to the surface particles within 1.5 H, the prototype that led to `csf` (2026-12-07).
Figures, not a test.
"""

import argparse
import math

import numpy as np

import upf
from upf.kernels import cubic_spline, cubic_spline_gradient

SPACING = 0.0025  # m
RHO0 = 1000.0


def material(args, sigma):
    water = {"type": "liquid", "density": RHO0, "viscosity": args.viscosity,
             "surface_tension": sigma, "solver": {"name": args.solver}}
    if args.model and sigma > 0:
        water["surface_tension_model"] = args.model
    return {"water": water, "walls": {"type": "frozen"}}


def drop_scene(args, radius, sigma):
    half = round((2 * radius + 4 * SPACING) / SPACING) * SPACING
    return {"name": "drop", "gravity": [0, 0, 0], "particle_spacing": SPACING,
            "materials": material(args, sigma),
            "containers": [{"material": "walls", "min": [0, 0, 0], "max": [2 * half] * 3}],
            "fluid_blocks": [{"material": "water", "shape": "ball", "min": [half - radius] * 3,
                              "max": [half + radius] * 3}],
            "time": {"dt_max": args.dt}}


def slab_scene(args, sigma, width=0.04, thickness=0.04, height=0.16):
    return {"name": "slab", "gravity": [0, 0, 0], "particle_spacing": SPACING,
            "periodic": {"x": [0, width], "z": [0, width]},
            "materials": material(args, sigma),
            "containers": [{"material": "walls", "min": [0, 0, 0],
                            "max": [width, height, width]}],
            "fluid_blocks": [{"material": "water", "min": [0, (height - thickness) / 2, 0],
                              "max": [width, (height + thickness) / 2, width]}],
            "time": {"dt_max": args.dt}}


def liquid(sim):
    with sim.particles() as p:
        is_liquid = np.asarray(p["type"]) == 0  # ParticleType::Liquid
        return (np.array(p["position"])[is_liquid], np.array(p["velocity"])[is_liquid],
                np.array(p["pressure"])[is_liquid])


def simulation(args, scene):
    sigma = args.sigma
    if args.prototype_csf:
        scene["materials"]["water"]["surface_tension"] = 0
        scene["materials"]["water"].pop("surface_tension_model", None)
    sim = upf.Simulation.from_dict(scene, threads=args.threads)
    if args.prototype_csf:
        force = FittedCurvatureForce(sigma, SPACING, periodic=scene.get("periodic"))
        sim.add_force(force, types=["liquid"])
    return sim


def volume_radius(count):
    """The radius of a ball holding `count` particles of volume s^3."""
    return SPACING * math.cbrt(3 * count / (4 * math.pi))


def mean_pressure(args, scene, inside):
    """Mean pressure of the liquid `inside(x)` selects, every fifth step from 0.2 s to --end, its
    standard deviation, and the liquid's particle count."""
    sim = simulation(args, scene)
    samples = []
    while sim.time < args.end:
        sim.step()
        if sim.time < 0.2 or sim.step_count % 5:
            continue
        x, _, pressure = liquid(sim)
        samples.append(pressure[inside(x)].mean())
    return float(np.mean(samples)), float(np.std(samples)), len(x)


def laplace(args):
    slab, slab_sd, _ = mean_pressure(args, slab_scene(args, args.sigma),
                                     lambda x: np.abs(x[:, 1] - np.median(x[:, 1])) < 0.01)
    print(f"slab (flat face): {slab:.2f} Pa (sd {slab_sd:.2f})")
    for spacings in args.radii:
        inside, inside_sd, count = mean_pressure(
            args, drop_scene(args, spacings * SPACING, args.sigma),
            lambda x: np.linalg.norm(x - np.median(x, axis=0), axis=1) < volume_radius(len(x)) / 2)
        radius = volume_radius(count)
        expected = 2 * args.sigma / radius
        jump = inside - slab
        print(f"drop R = {spacings} s ({count} particles, R {radius * 1e3:.2f} mm): "
              f"{inside:.2f} Pa (sd {inside_sd:.2f}), jump {jump:.2f} Pa, "
              f"Laplace {expected:.2f} Pa, ratio {jump / expected:.3f}")


def rayleigh(args):
    for spacings in args.radii:
        sim = simulation(args, drop_scene(args, spacings * SPACING, args.sigma))
        with sim.particles() as p:
            is_liquid = np.asarray(p["type"]) == 0
            x = np.array(p["position"])
            count = int(is_liquid.sum())
            radius = volume_radius(count)
            omega = math.sqrt(8 * args.sigma / (RHO0 * radius**3))
            rate = args.amplitude * omega / 2
            d = x - x[is_liquid].mean(axis=0)
            v = np.array(p["velocity"])
            v[is_liquid] = rate * np.stack([-d[is_liquid, 0], -d[is_liquid, 1],
                                            2 * d[is_liquid, 2]], axis=1)
            p["velocity"][:] = v
        times, shape = [], []
        while sim.time < args.end:
            sim.step()
            if sim.step_count % 4:
                continue
            x, _, _ = liquid(sim)
            d = x - x.mean(axis=0)
            shape.append((d[:, 2]**2).mean() - 0.5 * ((d[:, 0]**2).mean() + (d[:, 1]**2).mean()))
            times.append(sim.time)
        shape = np.array(shape) - np.mean(shape[len(shape) // 3:])
        crossings = [times[k] for k in range(1, len(shape)) if shape[k - 1] * shape[k] < 0]
        peak = times[int(np.argmax(np.abs(shape)))]
        print(f"drop R = {spacings} s ({count} particles): Rayleigh period "
              f"{2 * math.pi / omega:.3f} s, first extreme expected at "
              f"{math.pi / (2 * omega):.3f} s; deformation peaked at {peak:.3f} s; "
              "crossings of its mean at " + ", ".join(f"{t:.3f}" for t in crossings))


class FittedCurvatureForce:
    """Prototype (not a registered model): F = sigma kappa grad c V / 0.51 on the particles with
    |grad c| H > 0.3, c = sum V_j W_ij; kappa = -2 (a + c) of the quadric w = a u^2 + b uv + c v^2
    + d u + e v + f fitted to the surface particles within 1.5 H in the frame of the normal
    -grad c / |grad c|, then averaged with the kernel over surface neighbours. 0.51: what the
    colour gradient of a particle face sums to per unit area at H = 2 s (flat lattice face)."""

    def __init__(self, sigma, spacing, periodic=None):
        from scipy.spatial import cKDTree  # python3-scipy; only this prototype needs it
        self.tree_type = cKDTree
        self.sigma, self.s, self.support = sigma, spacing, 2 * spacing
        self.box = None
        if periodic:
            box = [1.0, 1.0, 1.0]
            for axis, name in enumerate("xyz"):
                if name in periodic:
                    box[axis] = periodic[name][1] - periodic[name][0]
            self.box = np.array(box)

    def pairs(self, tree, x, reach):
        found = tree.query_pairs(reach, output_type="ndarray")
        i = np.concatenate([found[:, 0], found[:, 1]])
        j = np.concatenate([found[:, 1], found[:, 0]])
        d = x[i] - x[j]
        if self.box is not None:
            d -= self.box * np.round(d / self.box)
        return i, j, d

    def __call__(self, p):
        # A periodic world hands over its images too (same id, shifted): compute on one copy of
        # each particle and give its images its force.
        _, first, copy_of = np.unique(np.asarray(p.id), return_index=True, return_inverse=True)
        return self.force(np.asarray(p.position, dtype=np.float64)[first])[copy_of]

    def force(self, x):
        n, volume, H = len(x), self.s**3, self.support
        if self.box is not None:
            x = np.mod(x, self.box)
        tree = self.tree_type(x, boxsize=self.box)
        i, j, d = self.pairs(tree, x, H)
        r = np.linalg.norm(d, axis=1)
        g = cubic_spline_gradient(d, H)
        grad_c = np.stack([np.bincount(i, weights=volume * g[:, k], minlength=n)
                           for k in range(3)], axis=1)
        size = np.linalg.norm(grad_c, axis=1)
        surface = size * H > 0.3
        normal = np.zeros((n, 3))
        normal[surface] = -grad_c[surface] / size[surface, None]
        pick = np.where(np.abs(normal[:, 0]) < 0.9, 1.0, 0.0)
        t1 = np.cross(normal, np.stack([pick, 1 - pick, np.zeros(n)], axis=1))
        t1 /= np.maximum(np.linalg.norm(t1, axis=1, keepdims=True), 1e-12)
        t2 = np.cross(normal, t1)
        fi, fj, fd = self.pairs(tree, x, 1.5 * H)
        both = surface[fi] & surface[fj]
        fi, fd = fi[both], -fd[both]  # x_j - x_i
        u = np.einsum("ij,ij->i", fd, t1[fi])
        v = np.einsum("ij,ij->i", fd, t2[fi])
        w = np.einsum("ij,ij->i", fd, normal[fi])
        phi = np.stack([u * u, u * v, v * v, u, v, np.ones_like(u)], axis=1)
        m = np.zeros((n, 6, 6))
        b = np.zeros((n, 6))
        np.add.at(m, fi, phi[:, :, None] * phi[:, None, :])
        np.add.at(b, fi, phi * w[:, None])
        m[:, 5, 5] += 1  # the particle itself, at the origin of its frame
        fitted = surface & (np.bincount(fi, minlength=n) >= 8)
        m[~fitted] = np.eye(6)
        b[~fitted] = 0
        coefficients = np.linalg.solve(m + 1e-12 * self.s**4 * np.eye(6), b[:, :, None])[:, :, 0]
        kappa = np.where(fitted, -2 * (coefficients[:, 0] + coefficients[:, 2]), 0.0)
        near = fitted[i] & fitted[j]
        w0 = float(cubic_spline(0.0, H))
        weights = cubic_spline(r[near], H)
        total = np.bincount(i[near], weights=weights * kappa[j[near]], minlength=n) + w0 * kappa
        norm = np.bincount(i[near], weights=weights, minlength=n) + w0
        kappa = np.where(fitted, total / norm, 0.0)
        return self.sigma * kappa[:, None] * grad_c * volume / 0.51


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("measure", choices=["laplace", "rayleigh"])
    parser.add_argument("--radii", type=float, nargs="+", default=[8], help="in spacings")
    parser.add_argument("--sigma", type=float, default=0.0728, help="N/m")
    parser.add_argument("--viscosity", type=float, default=1e-4, help="m^2/s")
    parser.add_argument("--dt", type=float, default=4e-4, help="the step's upper bound, s")
    parser.add_argument("--end", type=float, default=None, help="s (laplace 0.6, rayleigh 1.5)")
    parser.add_argument("--amplitude", type=float, default=0.1, help="of R (rayleigh)")
    parser.add_argument("--solver", default="pcisph")
    parser.add_argument("--model", default="", help="a registered surface tension model")
    parser.add_argument("--prototype-csf", action="store_true")
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    if args.end is None:
        args.end = 0.6 if args.measure == "laplace" else 1.5
    laplace(args) if args.measure == "laplace" else rayleigh(args)


if __name__ == "__main__":
    main()
