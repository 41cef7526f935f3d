// The scene keys "emitters" and "sinks" (docs/emitters.md): read, checked and built into the
// world as particle sources (emitter.h, sink.h), with each nozzle's walls as frozen particles.
#pragma once

#include "framework/scene/scene_section.h"

namespace upf {

class Registry;

SceneSection emitters_scene_section();
SceneSection sinks_scene_section();
// Both sections.
void register_sources(Registry& registry);

}  // namespace upf
