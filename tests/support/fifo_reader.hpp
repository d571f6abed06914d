#pragma once
// Reads what a writer sends through a FIFO, in a thread of its own: opened without
// blocking before the writer starts, so that the writer's open never waits, and given
// up after 60 s, so that a test whose writer never comes cannot hang.

#include <filesystem>
#include <string>
#include <thread>

namespace crux::testing {

class FifoReader {
 public:
  explicit FifoReader(const std::filesystem::path& fifo);
  ~FifoReader();
  FifoReader(const FifoReader&) = delete;
  FifoReader& operator=(const FifoReader&) = delete;

  bool opened() const { return fd_ >= 0; }
  // Waits until the writer has closed the FIFO (or 60 s have passed) and returns what it wrote.
  const std::string& text();

 private:
  int fd_;
  std::string text_;
  std::thread thread_;
};

}  // namespace crux::testing
