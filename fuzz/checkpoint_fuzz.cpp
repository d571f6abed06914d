// libFuzzer harness for a long run's checkpoint file (read_checkpoint): its state or an
// InputError, nothing else. Each input is read as given, then with its SHA-256 made right
// and read as the checkpoint of the run it names, since random bytes almost never match
// the digest or the identity and would not reach the framing of the identity and state.
// The seed is a real checkpoint.bin of a crux train run (fuzz/corpus/checkpoint).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "common/checkpoint_stream.hpp"
#include "common/input_error.hpp"
#include "common/sha256.hpp"
#include "experiments/run_checkpoint.hpp"

namespace {

constexpr std::string_view kMagic = "crux-checkpoint 1\n";
constexpr std::size_t kDigestLine = 7 + 64 + 1;  // "sha256 <hex>\n"

const std::filesystem::path& checkpoint_scratch() {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("crux-checkpoint-fuzz-" + std::to_string(::getpid()) + ".bin");
  return file;
}

void read_as_checkpoint(const std::string& bytes, const std::string& identity) {
  std::ofstream(checkpoint_scratch(), std::ios::binary | std::ios::trunc) << bytes;
  try {
    crux::read_checkpoint(checkpoint_scratch(), identity);
  } catch (const crux::InputError&) {
  }
}

// The identity that `payload` (what follows the digest line) starts with; "" if none.
std::string named_identity(std::string_view payload) {
  try {
    crux::CheckpointReader in(payload, "fuzz");
    return in.text();
  } catch (const crux::InputError&) {
    return {};
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  read_as_checkpoint(bytes, "");
  if (bytes.size() < kMagic.size() + kDigestLine) return 0;
  const std::string payload = bytes.substr(kMagic.size() + kDigestLine);
  const std::string fixed = std::string(kMagic) + "sha256 " + crux::sha256_hex(payload) + "\n" + payload;
  read_as_checkpoint(fixed, named_identity(payload));
  return 0;
}
