#include "framework/core/state_stream.h"

#include "framework/core/errors.h"

namespace upf {

void StateReader::section(std::string_view name) {
  const std::string found = get_string();
  if (found != name)
    fail("expected section '" + std::string(name) + "', found '" + found.substr(0, 40) + "'");
  section_ = found;
}

std::string StateReader::get_string() {
  const auto n = get<std::uint64_t>();
  if (n > remaining()) fail("a string longer than the file");
  const char* p = take(std::size_t(n));
  return std::string(p, std::size_t(n));
}

void StateReader::fail(const std::string& what) const {
  throw InputError(source_, "damaged (in section '" + section_ + "', byte " + std::to_string(pos_) +
                                "): " + what);
}

const char* StateReader::take(std::size_t n) {
  if (n > remaining()) fail("the file ends early (truncated?)");
  const char* p = bytes_.data() + pos_;
  pos_ += n;
  return p;
}

}  // namespace upf
