// Files that are either complete or absent: a writer works in a private folder
// beside the target and what it made is renamed into place afterwards, so a
// run that is interrupted or killed never leaves a half-written result.
// Every write and every close is checked (OutputFile): a full disk or a file-size
// limit stops the writer before anything is renamed, and the files already in
// place stay as they were.
#pragma once
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace aster {

// A file opened for writing whose every write and whose close are checked: the
// first failure is kept and thrown by close() (or at once by write()) as
// aster::Error("cannot write <path>: <strerror>", e.g. "No space left on device").
// The destructor closes without checking: it runs on error paths only, the
// normal path calls close().
class OutputFile {
 public:
  explicit OutputFile(const std::filesystem::path& path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Buffered; a failure sets the stream's badbit and is thrown by close().
  std::ostream& stream();
  void write(std::string_view text);
  void put(char c);
  void printf(const char* format, ...) __attribute__((format(printf, 2, 3)));
  // Flushes and closes; throws the first failure since the file was opened.
  void close();
  const std::filesystem::path& path() const { return path_; }

 private:
  class Buffer;
  std::filesystem::path path_;
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<std::ostream> stream_;
  void throwIfFailed();
};

// Writes `text` to a new file `path` through OutputFile (checked writes and close).
void writeTextFile(const std::filesystem::path& path, std::string_view text);

// The files of one run: those the study read, which the program never writes over,
// and those the run wrote, so that a second write to one file is an append or goes
// to another file by the writer's choice, never an unnoticed replacement.
class RunFiles {
 public:
  // A file the study read and how ("LIRE_MAILLAGE at a.lua:3"), for messages.
  void addInput(const std::filesystem::path& file, const std::string& how);
  // How `file` was read when it is an input of the study (the same path, or the
  // same device and inode: a link or another spelling), else "". A file the run
  // wrote before reading it back is its own output, not an input.
  std::string inputOf(const std::filesystem::path& file) const;
  bool written(const std::filesystem::path& file) const;
  void addWritten(const std::filesystem::path& file);
  // folder/stem + ext, else stem-2, stem-3, ...: the first that is neither an input
  // nor written by this run, nor `taken(stem)` says taken.
  std::filesystem::path fresh(const std::filesystem::path& folder, const std::string& stem, const std::string& ext,
                              const std::function<bool(const std::string&)>& taken = {}) const;
  // Removes the files of `folder` whose names `match` accepts, except inputs and
  // files this run wrote: what an earlier run left under this run's names.
  // Returns the names removed.
  std::vector<std::string> removeStale(const std::filesystem::path& folder,
                                       const std::function<bool(const std::string&)>& match) const;

 private:
  struct Input {
    std::string how;
    bool hasId = false;
    unsigned long long device = 0, inode = 0;
  };
  std::map<std::string, Input> inputs_;
  std::set<std::string> written_;
};

// Runs write(<private folder>/<target file name>) and then renames every file it
// made into the target's folder, the target itself last (a .pvd names its .vtu
// files: they are in place before it is). On failure nothing is renamed and the
// private folder is removed; the error (aster::Error) says what failed and names
// the files by their place in the target's folder. With `files`, no file is
// renamed over an input of the study (aster::Error naming it and how it was
// read), and the files made are recorded as written by the run.
void writeAtomically(const std::filesystem::path& target,
                     const std::function<void(const std::filesystem::path&)>& write, RunFiles* files = nullptr);

// writeAtomically of `text` at the end of `target`'s content (copied first when
// `keep`, else the file starts afresh): several writes of a run to one file
// follow each other, and the file is still complete or absent.
void appendAtomically(const std::filesystem::path& target, std::string_view text, bool keep, RunFiles* files);

// "<stem>_<digits><ext>": the per-instant files of a collection (RESU_12.vtu).
bool isNumberedFile(const std::string& name, const std::string& stem, const std::string& ext);

}  // namespace aster
