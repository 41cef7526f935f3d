// What a run owns in its output folder. Every file a run writes is first recorded, one line per
// file appended to RUN_DIR/upf_manifest.txt (each line in one write, so a crash leaves at worst a
// torn last line, which the reader skips). A new run into the folder removes exactly what the
// previous run's manifest lists, never anything else: a user's own files beside a run survive,
// and a folder that no upf run recorded is refused unless the caller asks to overwrite it.
// Symbolic links inside the folder are never followed: a listed entry that is (or lies behind) a
// link is not ours, because upf never makes links. docs/robustness.md, "What a run may delete".
#pragma once

#include <cstddef>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace upf {

// The run's record of the scene it was made from, in its output folder (a name of its own, so
// that a user's scene.json beside a run is never replaced).
inline constexpr const char* kSceneRecordFile = "upf_scene.json";

class RunManifest {
 public:
  static constexpr const char* kFileName = "upf_manifest.txt";

  // A new run into `dir` (made if missing). Throws InputError naming `dir` when it holds entries
  // but no manifest, unless `overwrite` (then the files at names this run claims are replaced
  // and nothing else is removed). Removes nothing yet: see clear_previous.
  static RunManifest for_new_run(const std::filesystem::path& dir, bool overwrite);
  // A run that continues the one recorded in `dir` (resume; `upf render` adding pictures): its
  // entries stay claimed and new ones are appended; a folder without a manifest gets one.
  static RunManifest for_continued_run(const std::filesystem::path& dir);

  // Removes the regular files the previous run listed (and their leftover ".tmp" twins), then the
  // folders it made if they are empty, and starts this run's manifest. Returns the files removed.
  std::size_t clear_previous();
  // Records `relative` (a path inside the folder, '/'-separated) before it is written. Throws
  // InputError when something not ours is already there (a user's file, a link, a folder) or a
  // link lies on the way.
  void claim(const std::string& relative);
  void claim(const std::vector<std::string>& relatives);
  // Records and makes the folder `relative`.
  void claim_directory(const std::string& relative);
  // Whether the previous run's manifest was found (its files are what clear_previous removes).
  bool had_previous() const { return had_previous_; }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  RunManifest(std::filesystem::path dir, bool overwrite)
      : dir_(std::move(dir)), overwrite_(overwrite) {}
  // Starts the manifest anew (header only), atomically.
  void start();
  // Appends "<kind> <relative>\n" in one write.
  void append(char kind, const std::string& relative);
  // Throws unless every folder on the way to `relative` is a real folder (or missing).
  void check_no_link_on_the_way(const std::string& relative) const;

  std::filesystem::path dir_;
  bool overwrite_ = false;
  bool had_previous_ = false;
  bool started_ = false;
  std::set<std::string> listed_;            // this run's entries
  std::set<std::string> previous_;          // the previous run's entries (removed or to remove)
  std::vector<std::string> previous_dirs_;  // the folders it made
};

// The entries of a manifest's text: "f PATH" files and "d PATH" folders, each a relative path
// with no "..", "." or empty component; anything else (a torn last line, a hostile entry) is
// skipped. Exposed for the tests.
struct ManifestEntries {
  std::vector<std::string> files, dirs;
  bool valid_header = false;
};
ManifestEntries parse_manifest(const std::string& text);

}  // namespace upf
