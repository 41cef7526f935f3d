#include "framework/scene/world_setting_specs.h"

namespace upf {

// The defaults repeat those of TimeSettings, WorldSettings and OutputDesc (the reader keeps the
// struct's value for an absent key); a unit test holds the two in step.

std::vector<ParamSpec> time_setting_specs() {
  return {
      {"end", "s", 1.0, 0, 1e7,
       "simulated end time; upf run --end T overrides it; the last step is shortened so that "
       "the run ends exactly at end",
       false, true},
      {"dt_min", "s", 1e-6, 0, 10, "lower bound on the adaptive step; it must be <= dt_max", false,
       true},
      {"dt_max", "s", 5e-3, 0, 10, "upper bound on the adaptive step", false, true},
      {"cfl", "1", 0.4, 0, 1,
       "CFL number: dt <= cfl * s / v_max (PCISPH), dt <= cfl * s / (sqrt(k) + v_max) (SPH); "
       "WCSPH has its own cfl parameter",
       false, true},
      {"fixed_dt", "s", 0, 0, 10,
       "if > 0, every step uses this dt, ignoring the CFL number, the viscous limit, dt_min and "
       "dt_max"},
  };
}

std::vector<ParamSpec> stability_setting_specs() {
  return {
      {"max_speed", "m/s", 100, 0, 1e6,
       "a particle faster than this stops the run as unstable, with exit code 3", false, true},
  };
}

std::vector<ParamSpec> neighbour_setting_specs() {
  return {
      // Not `integer`: the reader truncates a fractional value, as it always has.
      {"reorder_every", "steps", 10, 0, 1e6,
       "particles are reordered in memory by grid cell every this many steps, for locality; 0 "
       "disables reordering; fractional values are truncated; results are bitwise identical "
       "with or without reordering"},
  };
}

std::vector<ParamSpec> output_setting_specs() {
  return {
      {"fps", "1/s", 30, 0, 1e6,
       "frames per simulated second; steps land exactly on every n / fps, where frame n is "
       "written, and a last frame is written at the end",
       false, true},
      {"size_warning", "GB", 20, 0, 1e9,
       "upf run warns before the first step when its frames would take more than this many "
       "gigabytes (10^9 bytes; the uncompressed size, which compression only lowers)"},
      {"surface_voxel", "spacings", 0.5, 0.05, 1,
       "voxel size of the liquid surface's level set (formats \"surface\", \"surface_vdb\"), "
       "in particle spacings; smaller gives a finer mesh, about 1 / voxel^2 times the triangles "
       "and 1 / voxel^3 times the memory and time"},
      {"surface_memory", "GB", 4, 1e-6, 1e6,
       "the liquid surface's grids may take at most this many gigabytes (estimated before the "
       "first step at 8 bytes per voxel of the liquid present then; a finer surface_voxel past "
       "it is an error)"},
      {"probe_every", "steps", 1, 0, 1e9,
       "probes.csv, body_forces.csv and the grains' dem_<model>_walls.csv get a row every this "
       "many "
       "steps, and at every frame; "
       "0: at frames only (with a device, each probes.csv row downloads the particles)",
       true},
  };
}

std::vector<WorldSettingSection> world_setting_sections() {
  return {
      {"/time", "end time and time-step control", time_setting_specs()},
      {"/stability", "limits that stop an unstable run", stability_setting_specs()},
      {"/neighbours", "neighbour search settings", neighbour_setting_specs()},
      {"/output", "frames (besides the field and format lists)", output_setting_specs()},
  };
}

}  // namespace upf
