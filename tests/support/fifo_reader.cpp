#include "support/fifo_reader.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <chrono>

namespace crux::testing {

FifoReader::FifoReader(const std::filesystem::path& fifo) : fd_(::open(fifo.c_str(), O_RDONLY | O_NONBLOCK)) {
  thread_ = std::thread([this] {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    std::array<char, 4096> buffer;
    bool written = false;
    while (fd_ >= 0 && std::chrono::steady_clock::now() < deadline) {
      const ssize_t n = ::read(fd_, buffer.data(), buffer.size());
      if (n > 0) {
        text_.append(buffer.data(), static_cast<std::size_t>(n));
        written = true;
      } else if (n == 0 && written) {
        break;  // the writer closed it (before any writer, a read also finds no data)
      } else {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    }
  });
}

FifoReader::~FifoReader() {
  if (thread_.joinable()) thread_.join();
  if (fd_ >= 0) ::close(fd_);
}

const std::string& FifoReader::text() {
  if (thread_.joinable()) thread_.join();
  return text_;
}

}  // namespace crux::testing
