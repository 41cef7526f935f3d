// The state of a world or a run as a flat byte stream in memory, for checkpoints (written to disk
// by framework/checkpoint/checkpoint_file.h). Components write their state in a fixed order, each
// part under a named section; the reader checks every section name and every length against
// what is left, so a truncated, corrupted or mismatched stream is
// an InputError that names the checkpoint file and the section, never a crash or a silent wrong
// start. Values are stored in the machine's own representation: checkpoints move between runs
// of one build, not between architectures.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace upf {

class StateWriter {
 public:
  // Marks the start of a named part; the reader expects the same name at the same place.
  void section(std::string_view name) { put_string(std::string(name)); }

  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    append(&value, sizeof(T));
  }
  template <class T>
  void put_vector(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put(std::uint64_t(values.size()));
    append(values.data(), values.size() * sizeof(T));
  }
  void put_string(const std::string& s) {
    put(std::uint64_t(s.size()));
    append(s.data(), s.size());
  }

  const std::vector<char>& bytes() const { return bytes_; }

 private:
  void append(const void* data, std::size_t n) {
    if (n == 0) return;
    const std::size_t at = bytes_.size();
    bytes_.resize(at + n);
    std::memcpy(bytes_.data() + at, data, n);
  }

  std::vector<char> bytes_;
};

class StateReader {
 public:
  // `source` names the stream in errors (the checkpoint file).
  StateReader(std::vector<char> bytes, std::string source)
      : bytes_(std::move(bytes)), source_(std::move(source)) {}

  // Throws unless the next part is `name`.
  void section(std::string_view name);

  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    std::memcpy(&value, take(sizeof(T)), sizeof(T));
    return value;
  }
  template <class T>
  void get_vector(std::vector<T>& out) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto n = get<std::uint64_t>();
    if (n > remaining() / (sizeof(T) > 0 ? sizeof(T) : 1)) fail("an array longer than the file");
    out.resize(std::size_t(n));
    if (n > 0)
      std::memcpy(out.data(), take(std::size_t(n) * sizeof(T)), std::size_t(n) * sizeof(T));
  }
  std::string get_string();

  // Throws unless `matches`, saying that `what` differs from this run's (the checkpoint
  // belongs to another scene).
  void expect(bool matches, const std::string& what) const {
    if (!matches) fail(what + " does not match the scene: the checkpoint is of another run");
  }
  [[noreturn]] void fail(const std::string& what) const;
  bool at_end() const { return pos_ == bytes_.size(); }
  std::size_t remaining() const { return bytes_.size() - pos_; }

 private:
  const char* take(std::size_t n);

  std::vector<char> bytes_;
  std::string source_;
  std::string section_ = "header";
  std::size_t pos_ = 0;
};

}  // namespace upf
