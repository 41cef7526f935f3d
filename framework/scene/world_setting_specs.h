// The numbers of the scene's world-settings sections (/time, /stability, /neighbours, /output) as
// parameter specs: the scene reader checks them against these tables and `upf info` prints them,
// so the documented ranges are the ones enforced.
#pragma once

#include <string>
#include <vector>

#include "framework/params/param_spec.h"

namespace upf {

struct WorldSettingSection {
  std::string path;  // the JSON path of the section: "/time"
  std::string summary;
  std::vector<ParamSpec> params;
};

std::vector<ParamSpec> time_setting_specs();
std::vector<ParamSpec> stability_setting_specs();
std::vector<ParamSpec> neighbour_setting_specs();
std::vector<ParamSpec> output_setting_specs();  // the numbers only: not "fields" or "formats"

// Every section above, in the order the scene format describes them.
std::vector<WorldSettingSection> world_setting_sections();

}  // namespace upf
