#pragma once
// crux wall's outputs: a generated wall, and a wall file's summary with the moving grid
// placed on a limb, as JSON or text.

#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "agent_space/moving_grid.hpp"
#include "ik/ik_result.hpp"
#include "wall/wall.hpp"

namespace crux {

// The start holds' ids by limb name.
nlohmann::ordered_json start_holds_json(const Wall& wall);
// "right hand 3, left hand 5, right foot 1, left foot 2" (hold ids).
std::string start_holds_text(const Wall& wall);

// `start` is the start check's result; `solver` the IK solver that made it.
nlohmann::ordered_json generated_wall_json(const std::string& file, const Wall& wall, std::uint64_t seed,
                                           const IkResult& start, const std::string& solver);
std::string generated_wall_text(const std::string& file, const Wall& wall, const IkResult& start,
                                const std::string& solver);

// A moving grid placed on a free limb, with its parameters.
struct PlacedGrid {
  Limb limb;
  GridPlacement placement;
  GridParameters parameters;
};

nlohmann::ordered_json wall_summary_json(const std::string& file, const Wall& wall, const IkResult& start,
                                         const std::optional<PlacedGrid>& grid);
std::string wall_summary_text(const std::string& file, const Wall& wall, const IkResult& start,
                              const std::optional<PlacedGrid>& grid);

}  // namespace crux
