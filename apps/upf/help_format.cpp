#include "help_format.h"

#include <map>

namespace upf::app {

std::string placeholder_for(const CLI::Option& option) {
  static const std::map<std::string, std::string> kByName = {{"out", "DIR"},
                                                             {"threads", "N"},
                                                             {"end", "T"},
                                                             {"solver", "NAME"},
                                                             {"checkpoint-every", "DURATION"},
                                                             {"set", "PTR=VALUE"},
                                                             {"resume", "RUN_DIR"},
                                                             {"color-by", "FIELD"},
                                                             {"size", "WxH"},
                                                             {"samples", "N"},
                                                             {"range", "LOW,HIGH"},
                                                             {"walls", "STYLE"},
                                                             {"frames", "A:B"},
                                                             {"solvers", "NAMES"},
                                                             {"plot-script", "FILE"},
                                                             {"screenshot", "FILE"},
                                                             {"exit-after", "N"}};
  if (option.get_lnames().empty()) return "VALUE";
  const auto it = kByName.find(option.get_lnames().front());
  return it == kByName.end() ? "VALUE" : it->second;
}

std::string PlainHelpFormatter::make_option_opts(const CLI::Option* option) const {
  // A flag takes no value; a positional's name already says what it is.
  if (option->get_expected_max() == 0 || !option->nonpositional()) return {};
  std::string text = " " + placeholder_for(*option);
  if (option->get_expected_max() > 1) text += " ...";
  return text;
}

std::string main_help_footer() {
  return R"(
Examples:
  upf run samples/dam_break.json --threads 2          frames, metrics, probes into out/dam_break
  upf run samples/dam_break.json --render             ... then a PNG per frame and an MP4
  upf run SCENE --set /materials/water/viscosity=0.01 override a value by JSON pointer
  upf run --resume out/dam_break --end 3              continue (or extend) a run
  upf compare samples/dam_break.json --solvers pcisph,dfsph --end 0.5
  upf validate my_scene.json                          every problem with its JSON path
  upf info                                            solvers and parameters with units

Exit codes: 0 ok, 1 output failure, 2 bad input (file:/json/path: message), 3 unstable run
(last good frame written), 130 interrupted by Ctrl-C (checkpoint written; --resume continues).
Each command has its own help: upf run --help.)";
}

}  // namespace upf::app
