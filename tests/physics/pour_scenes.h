// A small pour for the tests that compare one way of running a scene with another (threads,
// device pipeline, MPI ranks): a hose pours into a 0.2 x 0.4 x 0.2 m tank whose floor is half
// drain, so particles are added and removed within the first 90 steps.
#pragma once

#include <nlohmann/json.hpp>

namespace upf::testing {

inline nlohmann::json hose_into_a_drain() {
  return {{"name", "hose_into_a_drain"},
          {"particle_spacing", 0.02},
          {"materials",
           {{"water", {{"type", "liquid"}, {"density", 1000}, {"viscosity", 0.001}}},
            {"walls", {{"type", "frozen"}}}}},
          {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {0.2, 0.4, 0.2}}}}},
          {"emitters",
           {{{"material", "water"},
             {"shape", "rectangle"},
             {"size", {0.1, 0.08}},
             {"center", {0.1, 0.3, 0.1}},
             {"direction", {0, -1, 0}},
             {"speed", 1.5}}}},
          {"sinks", {{{"min", {0, -1, 0}}, {"max", {0.1, 0.05, 0.2}}}}}};
}

// A short open channel: an inlet with an open-channel profile on its floor, and an outlet whose
// outflow buffer extrapolates the speed of the liquid arriving (solvers/sources/).
inline nlohmann::json channel_with_open_ends() {
  return {{"name", "channel_with_open_ends"},
          {"particle_spacing", 0.02},
          {"materials",
           {{"water", {{"type", "liquid"}, {"density", 1000}, {"viscosity", 0.001}}},
            {"walls", {{"type", "frozen"}}}}},
          {"containers", {{{"material", "walls"}, {"min", {0, 0, 0}}, {"max", {0.3, 0.2, 0.1}}}}},
          {"emitters",
           {{{"material", "water"},
             {"shape", "rectangle"},
             {"size", {0.1, 0.08}},
             {"width_axis", {0, 0, 1}},
             {"center", {0.03, 0.05, 0.05}},
             {"direction", {1, 0, 0}},
             {"speed", 1.5},
             {"profile", "open_channel"},
             {"nozzle", false}}}},
          {"sinks",
           {{{"min", {0.2, -1, -1}},
             {"max", {1, 1, 1}},
             {"outflow", {{"direction", {1, 0, 0}}, {"buffer", 3}}}}}}};
}

}  // namespace upf::testing
