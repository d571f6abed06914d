#include "learning/transfer_mode.hpp"

namespace crux {

const char* transfer_mode_name(TransferMode mode) {
  switch (mode) {
    case TransferMode::Paper:
      return "paper";
    case TransferMode::Informed:
      return "informed";
    case TransferMode::Prior:
      return "prior";
    case TransferMode::Seeded:
      return "seeded";
    case TransferMode::Shaping:
      return "shaping";
    case TransferMode::Ordered:
      return "ordered";
  }
  return "?";
}

std::optional<TransferMode> parse_transfer_mode(std::string_view name) {
  for (const TransferMode mode : {TransferMode::Paper, TransferMode::Informed, TransferMode::Prior,
                                  TransferMode::Seeded, TransferMode::Shaping, TransferMode::Ordered}) {
    if (name == transfer_mode_name(mode)) return mode;
  }
  return std::nullopt;
}

const char* transfer_mode_names() { return "paper, informed, prior, seeded, shaping or ordered"; }

}  // namespace crux
