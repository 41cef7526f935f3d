#include "framework/scene/surface_tension_keys.h"

#include "framework/materials/adhesion_contact_angle.h"
#include "framework/params/param_table_markdown.h"

namespace upf {

using nlohmann::json;

namespace {
constexpr double kMaxAdhesionRatio = 10;

std::vector<std::string> model_names(const Registry& registry) {
  std::vector<std::string> names;
  for (const auto& model : registry.surface_tension_models()) names.push_back(model.name);
  return names;
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "'" : ", '") + n + "'";
  return s;
}
}  // namespace

void read_surface_tension_keys(JsonInput& in, const json& node, const std::string& path,
                               const Registry& registry, Material& m) {
  if (auto name = in.string(node, path, "surface_tension_model", false)) {
    const std::vector<std::string> names = model_names(registry);
    bool known = false;
    for (const auto& n : names) known = known || n == *name;
    if (known) {
      m.surface_tension_model = *name;
    } else {
      std::string msg = "no surface tension model named '" + *name + "'";
      if (auto guess = did_you_mean(*name, names)) msg += " (did you mean '" + *guess + "'?)";
      in.problem(JsonInput::child(path, "surface_tension_model"),
                 msg + "; registered: " + joined(names));
    }
  }
  auto it = node.find("adhesion");
  if (it != node.end() && in.expect_object(*it, JsonInput::child(path, "adhesion"))) {
    const std::string where = JsonInput::child(path, "adhesion");
    for (auto pair = it->begin(); pair != it->end(); ++pair) {
      if (auto ratio = in.required_number(*it, where, pair.key(), 0, kMaxAdhesionRatio))
        m.adhesion[pair.key()] = *ratio;
    }
  }
  // The same wetting asked for as an equilibrium contact angle (adhesion_contact_angle.h).
  auto angles = node.find("contact_angle");
  if (angles == node.end()) return;
  const std::string where = JsonInput::child(path, "contact_angle");
  if (!in.expect_object(*angles, where)) return;
  for (auto pair = angles->begin(); pair != angles->end(); ++pair) {
    const std::string at = JsonInput::child(where, pair.key());
    auto degrees = in.required_number(*angles, where, pair.key(), 0, 180, false, "degrees");
    if (!degrees) continue;
    if (*degrees < kSmallestContactAngle) {
      in.problem(at, compact_number(*degrees) +
                         " degrees: Akinci's adhesion reaches contact angles "
                         "from " +
                         compact_number(kSmallestContactAngle) + " to " +
                         compact_number(kLargestContactAngle) +
                         " degrees; past that the liquid wets completely, running up the walls "
                         "as a film (docs/surface-tension.md)");
    } else if (m.adhesion.count(pair.key())) {
      in.problem(at, "'" + pair.key() + "' has an adhesion ratio too (" + path + "/adhesion/" +
                         pair.key() + "): give one of the two");
    } else {
      m.contact_angle[pair.key()] = *degrees;
      m.adhesion[pair.key()] = adhesion_ratio_for_contact_angle(*degrees);
    }
  }
}

void check_surface_tension_keys(JsonInput& in, const Registry& registry,
                                const SceneDescription& scene) {
  for (const Material& m : scene.materials) {
    if (m.type != ParticleType::Liquid) continue;
    const std::string path = "/materials/" + m.name;
    for (const auto& [name, ratio] : m.adhesion) {
      const std::string where =
          path + (m.contact_angle.count(name) ? "/contact_angle/" : "/adhesion/") + name;
      const Material* other = scene.material(name);
      if (!other && scene.rejected(name)) continue;  // its own problem is reported already
      if (!other) {
        std::vector<std::string> boundaries;
        for (const Material& o : scene.materials)
          if (o.type == ParticleType::Frozen || o.type == ParticleType::Rigid)
            boundaries.push_back(o.name);
        std::string msg = "no material named '" + name + "'";
        if (auto guess = did_you_mean(name, boundaries)) msg += " (did you mean '" + *guess + "'?)";
        in.problem(where,
                   msg + "; adhesion names frozen or rigid materials: " + joined(boundaries));
      } else if (other->type != ParticleType::Frozen && other->type != ParticleType::Rigid) {
        in.problem(where,
                   "'" + name + "' is a " + other->kind +
                       " material; adhesion names frozen or rigid materials (walls, bodies)");
      }
    }
    const std::string wetting =
        path + (m.contact_angle.size() == m.adhesion.size() ? "/contact_angle" : "/adhesion");
    if (!m.adhesion.empty() && m.param("surface_tension") <= 0) {
      in.problem(wetting,
                 "adhesion is a ratio to the surface tension's cohesion, and surface_tension is 0: "
                 "set /materials/" +
                     m.name + "/surface_tension (N/m, water 0.0728)");
    } else if (!m.adhesion.empty()) {
      const std::string model = surface_tension_model_of(m, registry);
      for (const auto& info : registry.surface_tension_models())
        if (info.name == model && !info.adhesion)
          in.problem(wetting, "the surface tension model '" + model +
                                  "' has no adhesion: without cohesion to hold it, the liquid "
                                  "would spread over every wall it touches as a film "
                                  "(docs/surface-tension.md); for wetting use "
                                  "surface_tension_model 'akinci2013', or remove this key");
    }
  }
  // One solver instance, one model: a pair of its liquids must not meet two force laws.
  for (std::size_t a = 0; a < scene.materials.size(); ++a)
    for (std::size_t b = 0; b < a; ++b) {
      const Material &ma = scene.materials[a], &mb = scene.materials[b];
      if (ma.type != ParticleType::Liquid || mb.type != ParticleType::Liquid) continue;
      if (ma.solver != mb.solver || ma.param("surface_tension") <= 0 ||
          mb.param("surface_tension") <= 0)
        continue;
      const std::string model_a = surface_tension_model_of(ma, registry);
      const std::string model_b = surface_tension_model_of(mb, registry);
      if (model_a != model_b)
        in.problem("/materials/" + ma.name + "/surface_tension_model",
                   "'" + model_a + "' differs from material '" + mb.name + "''s '" + model_b +
                       "'; liquids moved by one solver ('" + ma.solver +
                       "') must share a surface tension model");
    }
}

std::string surface_tension_model_of(const Material& m, const Registry& registry) {
  if (!m.surface_tension_model.empty()) return m.surface_tension_model;
  const auto& models = registry.surface_tension_models();
  return models.empty() ? std::string() : models.front().name;
}

}  // namespace upf
