#include "checkpoint_options.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "framework/core/errors.h"

namespace upf::app {

CheckpointPolicy parse_checkpoint_every(const std::string& text) {
  const std::string forms =
      "expected a duration such as 300s, 5m or 2h (wall-clock) or 0.5sim (simulated seconds), "
      "got '" +
      text + "'";
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    throw InputError("--checkpoint-every", forms);
  }
  const std::string unit = text.substr(used);
  CheckpointPolicy policy;
  if (unit == "s") {
    policy.every = value;
  } else if (unit == "m") {
    policy.every = value * 60;
  } else if (unit == "h") {
    policy.every = value * 3600;
  } else if (unit == "sim") {
    policy.every = value;
    policy.wall_clock = false;
  } else {
    throw InputError("--checkpoint-every", forms);
  }
  // A tiny interval would checkpoint at every step (or, before the schedule computed its next
  // time, spin for ever adding 1e-300 to it); a huge one is a typo. Wall-clock checkpoints
  // cost seconds of writing, so no closer than 1 s; simulated ones no closer than 1 us.
  const double lo = policy.wall_clock ? kMinWallClockEvery : kMinSimulatedEvery;
  if (!std::isfinite(policy.every) || policy.every < lo || policy.every > kMaxCheckpointEvery) {
    char range[160];
    std::snprintf(range, sizeof range, "%s intervals from %g s to %g s",
                  policy.wall_clock ? "wall-clock" : "simulated", lo, kMaxCheckpointEvery);
    throw InputError("--checkpoint-every", "'" + text + "' is outside the allowed range: " + range);
  }
  return policy;
}

std::string to_header(const ResumableRun& run) {
  nlohmann::json j;
  j["kind"] = "upf run";
  j["scene_text"] = run.scene_text;
  j["scene_source"] = run.scene_source;
  j["solver"] = run.solver;
  j["end_time"] = run.end_time ? nlohmann::json(*run.end_time) : nlohmann::json(nullptr);
  j["no_frames"] = run.no_frames;
  j["checkpoint_every"] = run.checkpoint_every;
  return j.dump();
}

ResumableRun from_header(const std::string& header, const std::string& where) {
  const nlohmann::json j = nlohmann::json::parse(header, nullptr, false);
  const auto text = [&](const char* key) {
    if (!j.contains(key) || !j[key].is_string())
      throw InputError(where, std::string("the checkpoint's header has no '") + key +
                                  "': it was not written by `upf run`");
    return j[key].get<std::string>();
  };
  if (j.is_discarded() || !j.is_object() || text("kind") != "upf run")
    throw InputError(where, "the checkpoint was not written by `upf run`");
  ResumableRun run;
  run.scene_text = text("scene_text");
  run.scene_source = text("scene_source");
  run.solver = text("solver");
  run.checkpoint_every = text("checkpoint_every");
  if (j.contains("end_time") && j["end_time"].is_number())
    run.end_time = j["end_time"].get<double>();
  run.no_frames = j.value("no_frames", false);
  return run;
}

}  // namespace upf::app
