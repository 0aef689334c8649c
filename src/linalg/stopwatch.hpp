// Adds the seconds of a scope to a statistics counter.
#pragma once
#include <chrono>

namespace aster::linalg {

class ScopedSeconds {
 public:
  ScopedSeconds(double& total, int& count) : total_(total), start_(std::chrono::steady_clock::now()) { ++count; }
  ~ScopedSeconds() {
    total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  ScopedSeconds(const ScopedSeconds&) = delete;
  ScopedSeconds& operator=(const ScopedSeconds&) = delete;

 private:
  double& total_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace aster::linalg
