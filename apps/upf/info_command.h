// `upf info`: what a scene may name (material kinds, solvers, world settings) with every
// parameter's unit, default and range; `--markdown` prints the same tables as the blocks the
// reference pages embed (scripts/update-reference-docs copies them in).
#pragma once

namespace upf::app {

int info_command(bool markdown);

}  // namespace upf::app
