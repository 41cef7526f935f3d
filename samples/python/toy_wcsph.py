"""A fluid solver written in Python: weakly compressible SPH (Becker & Teschner 2007, "Weakly
compressible SPH for free surface flows", SCA) in NumPy, registered by name beside upf's own.

    import upf, toy_wcsph
    registry = upf.Registry()
    toy_wcsph.register(registry)
    sim = upf.Simulation.from_file("samples/hydrostatic_tank.json", solver="toy_wcsph",
                                   registry=registry)

It is the paper's method with Akinci et al. 2012 boundaries, as upf's C++ WCSPH
(solvers/wcsph/wcsph_kernels.h), written for reading, not speed: every step builds its pair
arrays from the world's neighbour lists and reduces them with np.bincount.
"""

import numpy as np

import upf

LIQUID, RIGID, FROZEN = (upf.PARTICLE_TYPES[t] for t in ("liquid", "rigid", "frozen"))

PARAMS = [
    {"name": "speed_of_sound", "unit": "m/s", "default": 20.0, "min": 1.0, "max": 1e4,
     "description": "c in the Tait equation p = rho0 c^2 / 7 ((rho / rho0)^7 - 1)"},
    {"name": "alpha", "unit": "1", "default": 0.1, "min": 0.0, "max": 1.0,
     "description": "artificial viscosity (the paper's eq. 11)"},
    {"name": "cfl", "unit": "1", "default": 0.4, "min": 0.01, "max": 1.0,
     "description": "dt <= cfl * spacing / c"},
]


class ToyWCSPH(upf.Solver):
    def prepare(self, world):
        self.pairs = world.request_neighbours(["liquid"], ["liquid", "rigid", "frozen"])
        world.declare_scalar("density", exported=True)
        world.declare_scalar("pressure", exported=True)
        self.rest_density = {i: m["params"].get("density", 1000.0) for i, m in enumerate(world.materials)}
        self.errors = (0.0, 0.0)

    def max_time_step(self, world):
        return self.params["cfl"] * world.spacing / self.params["speed_of_sound"]

    def step(self, world, dt):
        x = np.asarray(world["position"], dtype=np.float64)
        v = np.asarray(world["velocity"], dtype=np.float64)
        m = np.asarray(world["mass"], dtype=np.float64)
        kind = np.asarray(world["type"])
        material = np.asarray(world["material"])
        volume = np.asarray(world["boundary_volume"], dtype=np.float64)
        n = len(x)
        own = (kind == LIQUID) & np.isin(material, self.materials)
        rho0 = np.array([self.rest_density[k] for k in range(len(self.rest_density))])[material]

        offsets, indices = world.neighbours(self.pairs)
        offsets = np.asarray(offsets, dtype=np.int64)
        i = np.repeat(np.arange(n), np.diff(offsets))
        j = np.asarray(indices, dtype=np.int64)
        keep = own[i]
        i, j = i[keep], j[keep]
        dx = x[i] - x[j]
        h = world.support_radius
        w = upf.cubic_spline(np.linalg.norm(dx, axis=1), h)
        grad = upf.cubic_spline_gradient(dx, h)
        fluid = kind[j] == LIQUID
        # Akinci et al. 2012: a boundary particle counts as Psi_b = rho0_i V_b of mass.
        pair_mass = np.where(fluid, m[j], rho0[i] * volume[j])

        density = m * upf.cubic_spline(0.0, h) + np.bincount(i, pair_mass * w, minlength=n)
        c = self.params["speed_of_sound"]
        pressure = np.maximum(rho0 * c * c / 7.0 * ((density / rho0) ** 7 - 1.0), 0.0)
        pressure[~own] = 0.0
        p_over_rho2 = np.zeros(n)
        p_over_rho2[own] = pressure[own] / (density[own] * density[own])

        # Pressure: -sum_j m_j (p_i/rho_i^2 + p_j/rho_j^2) grad W, boundaries with p_i only.
        coefficient = np.where(fluid, m[j] * (p_over_rho2[i] + p_over_rho2[j]),
                               pair_mass * p_over_rho2[i])
        # Artificial viscosity between approaching liquid particles.
        vx = np.einsum("ij,ij->i", v[i] - v[j], dx)
        half_h = 0.5 * h
        nu = 2.0 * self.params["alpha"] * half_h * c / (density[i] + density[j])
        pi_ij = np.where(fluid & (vx < 0), -nu * vx / (np.einsum("ij,ij->i", dx, dx)
                                                       + 0.01 * half_h * half_h), 0.0)
        coefficient += np.where(fluid, m[j] * pi_ij, 0.0)

        a = np.zeros((n, 3))
        for axis in range(3):
            a[:, axis] = -np.bincount(i, coefficient * grad[:, axis], minlength=n)
        a += np.asarray(world.gravity)
        pushed = world.coupling("liquid_force")  # forces from other materials or Python forces
        if pushed is not None:
            a += np.asarray(pushed, dtype=np.float64) / m[:, None]

        # Reactions on bodies (Akinci et al. 2012, eq. 11): what the pressure pushes on each
        # boundary particle, for the bodies' force sums.
        reactions = world.coupling("boundary_force")
        if reactions is not None:
            onto = ~fluid & (kind[j] == RIGID)
            force = (m[i] * pair_mass * p_over_rho2[i])[onto, None] * grad[onto]
            r = np.asarray(reactions)
            for axis in range(3):
                r[:, axis] += np.bincount(j[onto], force[:, axis], minlength=n).astype(r.dtype)

        # Symplectic Euler on the solver's own particles.
        v_new = v + dt * a
        world["velocity"][own] = v_new[own]
        world["position"][own] = (x + dt * v_new)[own]
        world["density"][:] = density
        world["pressure"][:] = pressure
        error = np.maximum(density[own] / rho0[own] - 1.0, 0.0)
        self.errors = (float(error.mean()) if error.size else 0.0,
                       float(error.max()) if error.size else 0.0)

    def stats(self):
        return {"iterations": 0, "avg_density_error": self.errors[0],
                "max_density_error": self.errors[1]}


def register(registry, name="toy_wcsph"):
    """Adds the toy solver to `registry` under `name`."""
    registry.add_solver(
        name, lambda params, materials: ToyWCSPH(params, materials), type="liquid",
        params=PARAMS, summary="weakly compressible SPH written in Python (a sample)",
        reference="Becker & Teschner 2007, Weakly compressible SPH for free surface flows",
        writes=["boundary_force"], reads_if_written=["liquid_force"])


def main():
    """The sample hydrostatic tank moved by the Python solver: prints the pressure at depth."""
    import argparse
    from pathlib import Path

    parser = argparse.ArgumentParser(description="the hydrostatic tank with toy_wcsph")
    parser.add_argument("--scene", type=Path,
                        default=Path(__file__).resolve().parent.parent / "hydrostatic_tank.json")
    parser.add_argument("--end", type=float, default=0.3)
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()
    registry = upf.Registry()
    register(registry)
    sim = upf.Simulation.from_file(args.scene, threads=args.threads, solver="toy_wcsph",
                                   registry=registry)
    sim.advance_to(args.end)
    x, pressure = sim.copy("position"), sim.copy("pressure")
    liquid = sim.copy("type") == LIQUID
    top = x[liquid, 1].max() + 0.5 * sim.spacing
    stats = sim.last_step()
    print(f"t = {sim.time:.3f} s, {sim.step_count} steps, density error avg "
          f"{100 * stats['avg_density_error']:.2f} % max {100 * stats['max_density_error']:.2f} %")
    for depth in (0.1, 0.2, 0.3, 0.4):
        near = liquid & (np.abs(top - x[:, 1] - depth) < 0.5 * sim.spacing)
        if near.any():
            print(f"depth {depth:.1f} m: p = {pressure[near].mean():8.1f} Pa, "
                  f"rho0 g d = {1000 * 9.81 * depth:8.1f} Pa")


if __name__ == "__main__":
    main()
