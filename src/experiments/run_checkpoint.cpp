#include "experiments/run_checkpoint.hpp"

#include "common/checkpoint_stream.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "common/sha256.hpp"

namespace crux {

namespace {

constexpr std::string_view kCheckpointMagic = "crux-checkpoint 1\n";
constexpr std::size_t kDigestLine = 7 + 64 + 1;  // "sha256 <hex>\n"

}  // namespace

std::string checkpoint_file_bytes(const std::string& identity, const std::string& state) {
  CheckpointWriter out;
  out.text(identity);
  out.text(state);
  const std::string payload = out.take();
  // A damaged file is refused before its state is read.
  return std::string(kCheckpointMagic) + "sha256 " + sha256_hex(payload) + "\n" + payload;
}

std::optional<std::string> read_checkpoint(const std::filesystem::path& file, const std::string& identity) {
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return std::nullopt;
  const std::string bytes = read_input_file(file.string(), "checkpoint");
  if (bytes.compare(0, kCheckpointMagic.size(), kCheckpointMagic) != 0)
    throw InputError(file.string(), "not a crux checkpoint");
  const std::string_view rest = std::string_view(bytes).substr(kCheckpointMagic.size());
  const std::string_view payload = rest.size() >= kDigestLine ? rest.substr(kDigestLine) : std::string_view();
  if (rest.size() < kDigestLine || rest.substr(0, 7) != "sha256 " || rest.substr(7, 64) != sha256_hex(payload)) {
    throw InputError(file.string(),
                     "the checkpoint is damaged (its SHA-256 does not match); pass --overwrite to start "
                     "afresh");
  }
  CheckpointReader in(payload, file.string());
  if (in.text() != identity) {
    throw InputError(file.string(),
                     "is the checkpoint of another run (other parameters or inputs, or another crux "
                     "build); pass --overwrite to start afresh, or give the parameters it was written "
                     "with");
  }
  std::string state = in.text();
  if (!in.at_end()) in.fail();
  return state;
}

}  // namespace crux
