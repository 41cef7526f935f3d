#include "framework/output/resumed_log.h"

#include <cstdint>
#include <system_error>
#include <utility>

#include "framework/core/errors.h"
#include "framework/core/state_stream.h"

namespace upf {

ResumableLog::ResumableLog(std::filesystem::path path, const std::string& header, bool resuming)
    : path_(std::move(path)) {
  if (resuming) return;
  out_.open(path_, std::ios::trunc);
  if (!out_) throw OutputError("cannot write " + path_.string());
  out_.precision(9);
  out_ << header;
}

void ResumableLog::flush() {
  out_.flush();
  if (!out_) throw OutputError("writing " + path_.string() + " failed (disk full?)");
}

void ResumableLog::save_state(StateWriter& out) {
  flush();
  out.put(std::uint64_t(std::filesystem::file_size(path_)));
}

void ResumableLog::restore_state(StateReader& in) {
  const auto length = in.get<std::uint64_t>();
  std::error_code ec;
  const auto now = std::filesystem::file_size(path_, ec);
  if (ec || now < length)
    in.fail(path_.string() + " is shorter than at the checkpoint (" + std::to_string(length) +
            " bytes)");
  out_.close();
  std::filesystem::resize_file(path_, length, ec);
  if (ec) throw OutputError("cannot truncate " + path_.string() + ": " + ec.message());
  out_.open(path_, std::ios::app);
  if (!out_) throw OutputError("cannot write " + path_.string());
  out_.precision(9);
}

}  // namespace upf
