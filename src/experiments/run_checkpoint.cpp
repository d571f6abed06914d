#include "experiments/run_checkpoint.hpp"

#include "common/checkpoint_stream.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"

namespace crux {

namespace {

constexpr std::string_view kMagic = "crux-checkpoint 1\n";

}  // namespace

std::string checkpoint_file_bytes(const std::string& identity, const std::string& state) {
  CheckpointWriter out;
  out.text(identity);
  out.text(state);
  return std::string(kMagic) + out.take();
}

std::optional<std::string> read_checkpoint(const std::filesystem::path& file, const std::string& identity) {
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return std::nullopt;
  const std::string bytes = read_input_file(file.string(), "checkpoint");
  if (bytes.compare(0, kMagic.size(), kMagic) != 0) throw InputError(file.string(), "not a crux checkpoint");
  CheckpointReader in(std::string_view(bytes).substr(kMagic.size()), file.string());
  if (in.text() != identity) {
    throw InputError(file.string(), "is the checkpoint of a run with other parameters or inputs; pass --overwrite to "
                                    "start afresh, or give the parameters it was written with");
  }
  std::string state = in.text();
  if (!in.at_end()) in.fail();
  return state;
}

}  // namespace crux
