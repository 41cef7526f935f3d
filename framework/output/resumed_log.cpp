#include "framework/output/resumed_log.h"

#include <system_error>

#include "framework/core/errors.h"

namespace upf {

void reopen_log_at(std::ofstream& log, const std::filesystem::path& path, std::uintmax_t length) {
  log.close();
  std::error_code ec;
  std::filesystem::resize_file(path, length, ec);
  if (ec) throw OutputError("cannot truncate " + path.string() + ": " + ec.message());
  log.open(path, std::ios::app);
  if (!log) throw OutputError("cannot write " + path.string());
}

}  // namespace upf
