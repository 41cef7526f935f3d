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

}  // namespace upf::testing
