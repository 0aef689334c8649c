#include "core/atomic_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <streambuf>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace aster {

namespace fs = std::filesystem;

// ------------------------------------------------------------ OutputFile

// A stream buffer on a file descriptor that keeps the first write error (errno).
class OutputFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd) { setp(data_, data_ + sizeof data_); }
  int fd() const { return fd_; }
  int error() const { return error_; }
  void fail(int error) {
    if (error_ == 0) error_ = error;
  }
  // Writes what is buffered; after a failure the rest is dropped (the file is lost anyway).
  bool drain() {
    const char* p = pbase();
    std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    while (n > 0 && error_ == 0) {
      const ssize_t w = ::write(fd_, p, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        fail(w < 0 ? errno : EIO);
        break;
      }
      p += w;
      n -= static_cast<std::size_t>(w);
    }
    setp(data_, data_ + sizeof data_);
    return error_ == 0;
  }
  int closeFile() {
    if (fd_ < 0) return 0;
    const int status = ::close(fd_);
    fd_ = -1;
    return status;
  }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  int fd_;
  int error_ = 0;
  char data_[1 << 16];
};

OutputFile::OutputFile(const fs::path& path) : path_(path) {
  int fd;
  do fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  while (fd < 0 && errno == EINTR);
  if (fd < 0) throw Error("cannot create " + path.string() + ": " + std::strerror(errno));
  buffer_ = std::make_unique<Buffer>(fd);
  stream_ = std::make_unique<std::ostream>(buffer_.get());
}

OutputFile::~OutputFile() {
  if (buffer_) buffer_->closeFile();
}

std::ostream& OutputFile::stream() { return *stream_; }

void OutputFile::throwIfFailed() {
  if (buffer_->error() != 0) throw Error("cannot write " + path_.string() + ": " + std::strerror(buffer_->error()));
  if (!*stream_) throw Error("cannot write " + path_.string() + ": the output stream failed");
}

void OutputFile::write(std::string_view text) {
  stream_->write(text.data(), static_cast<std::streamsize>(text.size()));
  if (buffer_->error() != 0) throwIfFailed();
}

void OutputFile::put(char c) { stream_->put(c); }

void OutputFile::printf(const char* format, ...) {
  char small[256];
  va_list args;
  va_start(args, format);
  va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(small, sizeof small, format, args);
  va_end(args);
  if (n < 0) {
    va_end(again);
    throw Error("cannot write " + path_.string() + ": bad format");
  }
  if (static_cast<std::size_t>(n) < sizeof small) {
    va_end(again);
    stream_->write(small, n);
    return;
  }
  std::string large(static_cast<std::size_t>(n) + 1, '\0');
  std::vsnprintf(large.data(), large.size(), format, again);
  va_end(again);
  stream_->write(large.data(), n);
}

void OutputFile::close() {
  stream_->flush();
  if (buffer_->closeFile() != 0) buffer_->fail(errno);
  throwIfFailed();
}

void writeTextFile(const fs::path& path, std::string_view text) {
  OutputFile out(path);
  out.write(text);
  out.close();
}

// ------------------------------------------------------------ RunFiles

namespace {

// One spelling per file: absolute, symbolic links of the existing part resolved.
std::string keyOf(const fs::path& p) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(p, ec);
  if (ec) return p.lexically_normal().string();
  const fs::path canonical = fs::weakly_canonical(absolute, ec);
  return (ec ? absolute.lexically_normal() : canonical).string();
}

bool identity(const fs::path& p, unsigned long long& device, unsigned long long& inode) {
  struct stat st;
  if (::stat(p.c_str(), &st) != 0) return false;
  device = st.st_dev;
  inode = st.st_ino;
  return true;
}

}  // namespace

void RunFiles::addInput(const fs::path& file, const std::string& how) {
  Input in;
  in.how = how;
  in.hasId = identity(file, in.device, in.inode);
  inputs_.emplace(keyOf(file), in);  // the first reading names it
}

std::string RunFiles::inputOf(const fs::path& file) const {
  const std::string key = keyOf(file);
  if (written_.count(key)) return "";
  if (const auto it = inputs_.find(key); it != inputs_.end()) return it->second.how;
  unsigned long long device, inode;
  if (!identity(file, device, inode)) return "";
  for (const auto& [path, in] : inputs_)
    if (in.hasId && in.device == device && in.inode == inode) return in.how + ", as " + path;
  return "";
}

bool RunFiles::written(const fs::path& file) const { return written_.count(keyOf(file)) > 0; }

void RunFiles::addWritten(const fs::path& file) { written_.insert(keyOf(file)); }

fs::path RunFiles::fresh(const fs::path& folder, const std::string& stem, const std::string& ext,
                         const std::function<bool(const std::string&)>& taken) const {
  for (int n = 1;; ++n) {
    const std::string name = n == 1 ? stem : stem + "-" + std::to_string(n);
    const fs::path p = folder / (name + ext);
    if (inputOf(p).empty() && !written(p) && !(taken && taken(name))) return p;
  }
}

std::vector<std::string> RunFiles::removeStale(const fs::path& folder,
                                               const std::function<bool(const std::string&)>& match) const {
  std::vector<std::string> removed;
  std::error_code ec;
  std::vector<fs::path> candidates;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (match(name) && it->is_regular_file(ec)) candidates.push_back(it->path());
  }
  std::sort(candidates.begin(), candidates.end());
  for (const auto& p : candidates) {
    if (!inputOf(p).empty() || written(p)) continue;
    if (fs::remove(p, ec)) removed.push_back(p.filename().string());
  }
  return removed;
}

bool isNumberedFile(const std::string& name, const std::string& stem, const std::string& ext) {
  const std::size_t head = stem.size() + 1;
  if (name.size() <= head + ext.size() || name.compare(0, stem.size(), stem) != 0 || name[stem.size()] != '_' ||
      name.compare(name.size() - ext.size(), ext.size(), ext) != 0)
    return false;
  for (std::size_t i = head; i < name.size() - ext.size(); ++i)
    if (name[i] < '0' || name[i] > '9') return false;
  return true;
}

// ------------------------------------------------------------ writeAtomically

namespace {

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace

void writeAtomically(const fs::path& target, const std::function<void(const fs::path&)>& write, RunFiles* files) {
  // Past a file-size limit (ulimit -f) a write fails with EFBIG, reported as any
  // other write error, instead of SIGXFSZ ending the run.
  static const bool ignoreFileSizeSignal = [] { return std::signal(SIGXFSZ, SIG_IGN) != SIG_ERR; }();
  (void)ignoreFileSizeSignal;
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw Error("cannot create the folder " + dir.string() + ": " + ec.message());
  static unsigned counter = 0;
  const fs::path tmp = dir / ("." + target.filename().string() + ".partial-" + std::to_string(::getpid()) + "-" +
                              std::to_string(++counter));
  fs::create_directory(tmp, ec);
  if (ec) throw Error("cannot create the temporary folder " + tmp.string() + ": " + ec.message());
  try {
    try {
      write(tmp / target.filename());
    } catch (const Error& e) {
      // The private folder is no place the user knows: name the files where they were going.
      throw Error(replaceAll(e.what(), tmp.string() + "/", (dir / "").string()));
    }
    std::vector<fs::path> made;
    for (const auto& e : fs::directory_iterator(tmp)) made.push_back(e.path());
    std::sort(made.begin(), made.end(), [&](const fs::path& a, const fs::path& b) {
      const bool at = a.filename() == target.filename(), bt = b.filename() == target.filename();
      return at != bt ? bt : a < b;
    });
    if (made.empty() || made.back().filename() != target.filename())
      throw Error("internal error: the writer made no file " + target.filename().string());
    if (files)
      for (const auto& p : made) {
        const fs::path to = dir / p.filename();
        const std::string how = files->inputOf(to);
        if (!how.empty())
          throw Error(to.string() + " is an input of the study (" + how +
                      "): aster-lite never writes over a file the study read");
      }
    for (const auto& p : made) {
      fs::rename(p, dir / p.filename(), ec);
      if (ec) throw Error("cannot move " + p.string() + " to " + (dir / p.filename()).string() + ": " + ec.message());
      if (files) files->addWritten(dir / p.filename());
    }
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(tmp, ignored);
    throw;
  }
  fs::remove_all(tmp, ec);
}

void appendAtomically(const fs::path& target, std::string_view text, bool keep, RunFiles* files) {
  keep = keep && fs::exists(target);
  writeAtomically(
      target,
      [&](const fs::path& tmp) {
        OutputFile out(tmp);
        if (keep) {
          std::ifstream before(target, std::ios::binary);
          if (!before) throw Error("cannot read " + target.string() + " to add to it: " + std::strerror(errno));
          char chunk[1 << 16];
          while (before.read(chunk, sizeof chunk) || before.gcount() > 0)
            out.write(std::string_view(chunk, static_cast<std::size_t>(before.gcount())));
          if (before.bad()) throw Error("cannot read " + target.string() + " to add to it");
        }
        out.write(text);
        out.close();
      },
      files);
}

}  // namespace aster
