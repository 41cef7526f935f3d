// The scene keys "emitters" and "sinks" (docs/emitters.md): read, checked and built into the
// world as particle sources (emitter.h, sink.h), with each nozzle's walls as frozen particles.
#pragma once

#include "framework/scene/scene_section.h"

#include <string>

namespace upf {

class Registry;
struct EmitterDesc;
struct SceneDescription;

// The emitter of that name, as read from the scene's "emitters" (read before "sinks"); null when
// there is none.
const EmitterDesc* find_emitter(const SceneDescription& scene, const std::string& name);

SceneSection emitters_scene_section();
SceneSection sinks_scene_section();
// Both sections.
void register_sources(Registry& registry);

}  // namespace upf
