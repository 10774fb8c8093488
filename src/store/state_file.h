// The persistent state document: trakbox's "battery-backed RAM".
// One JSON file in the state directory, guarded by a CRC-32 over its data. Saves are atomic
// (write a temporary file, flush it to disk, rename it over the old one, flush the directory):
// a crash at any point leaves the old or the new state, never a mix. A file that fails its
// checksum or does not parse is renamed aside (never overwritten) and reported.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace tb::store {

std::uint32_t crc32(std::string_view bytes);

struct LoadOutcome {
  enum class Kind {
    fresh,    // no state file yet: defaults, nothing lost
    loaded,   // the document is in data
    corrupt,  // checksum, syntax, size or nesting failed, or a symbolic link: the file (or the link) was
              // kept aside, defaults apply
  };
  Kind kind = Kind::fresh;
  nlohmann::json data;              // the saved data when loaded
  std::filesystem::path kept_aside; // where a corrupt file was moved
  std::string reason;               // why it was judged corrupt (one line)
};

class StateFile {
 public:
  static constexpr const char* kFileName = "trakbox-state.json";
  static constexpr int kVersion = 1;
  // A state document is about 1 MB with a large database; a file beyond this is refused (kept aside)
  // before it is read, so a hostile or runaway file cannot take the memory and the start-up time.
  static constexpr std::uintmax_t kMaxBytes = 64u * 1024 * 1024;

  explicit StateFile(std::filesystem::path directory);

  const std::filesystem::path& directory() const { return dir_; }
  std::filesystem::path path() const { return dir_ / kFileName; }

  LoadOutcome load() const;
  // Returns false with a one-line reason on failure (the old file is then untouched). The file is
  // written mode 0600, and a directory this creates 0700: the document holds the credentials of
  // the element downloads.
  bool save(const nlohmann::json& data, std::string& error) const;
  // Takes group and other permissions off an existing state directory and document (written by an
  // older trakbox or by hand); one line for the log for each change made.
  std::vector<std::string> tighten_permissions() const;
  // Moves the current file aside as NAME.corrupt-TIMESTAMP (never overwriting anything) and returns
  // the new path; empty when there was nothing to move. For a file that passed its checksum but
  // whose content the program refused.
  std::filesystem::path keep_aside() const;

 private:
  std::filesystem::path dir_;
};

// Writes `text` to `target` so that a crash at any point leaves the old file or the new one, never a
// mix: a temporary file .NAME.tmp-PID beside it, written and flushed, renamed over the target, then
// the directory flushed. The file gets exactly `mode`. False with a one-line reason on failure.
bool write_file_atomically(const std::filesystem::path& target, std::string_view text, std::string& error,
                           unsigned mode = 0600);
inline constexpr const char* kTempInfix = ".tmp-";
// Removes the temporary files write_file_atomically leaves when the process is killed mid-save
// (.NAME.tmp-PID whose process is gone) from `dir`; returns what it removed.
std::vector<std::filesystem::path> remove_stale_temporaries(const std::filesystem::path& dir);

// Moves `file` aside as FILE.corrupt-YYYYMMDDTHHMMSSZ[-N]; never overwrites anything.
std::filesystem::path keep_aside(const std::filesystem::path& file);

// $XDG_STATE_HOME/trakbox, else $HOME/.local/state/trakbox, else ./trakbox-state.
std::filesystem::path default_state_directory();

}  // namespace tb::store
