#include "framework/run/output_fields.h"

#include <algorithm>

#include "framework/core/errors.h"
#include "framework/scene/json_input.h"

namespace upf {

std::vector<std::string> check_output_fields(const SceneDescription& scene,
                                             const Particles& particles) {
  std::vector<std::string> available;
  for (const auto& [name, field] : particles.scalar_fields())
    if (field.exported) available.push_back(name);
  for (const auto& [name, field] : particles.vector_fields())
    if (field.exported) available.push_back(name);
  std::sort(available.begin(), available.end());
  if (!scene.output.fields) return available;

  std::string list;
  for (const auto& name : available) list += (list.empty() ? "" : ", ") + name;
  std::vector<InputProblem> problems;
  const auto& fields = *scene.output.fields;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (std::find(available.begin(), available.end(), fields[i]) != available.end()) continue;
    std::string msg = "no solver of this scene exports a field '" + fields[i] + "'";
    if (auto guess = did_you_mean(fields[i], available)) msg += " (did you mean '" + *guess + "'?)";
    msg += "; fields available: " + (list.empty() ? std::string("none") : list);
    problems.push_back(
        {scene.source.string() + ":" + JsonInput::child("/output/fields", i), std::move(msg)});
  }
  if (!problems.empty()) throw InputError(std::move(problems));
  return fields;
}

}  // namespace upf
