#include "reports/wall_description.hpp"

#include <fmt/format.h>

#include "common/counted.hpp"
#include "common/printable.hpp"

namespace crux {

nlohmann::ordered_json start_holds_json(const Wall& wall) {
  nlohmann::ordered_json ids;
  for (int l = 0; l < kLimbCount; ++l) ids[enum_name(static_cast<Limb>(l))] = wall.holds[wall.start[l]].id;
  return ids;
}

std::string start_holds_text(const Wall& wall) {
  return fmt::format("right hand {}, left hand {}, right foot {}, left foot {}", wall.holds[wall.start[0]].id,
                     wall.holds[wall.start[1]].id, wall.holds[wall.start[2]].id, wall.holds[wall.start[3]].id);
}

namespace {

// ", inclined 40 degrees (overhanging; heights along the wall)", or "" for a vertical wall.
std::string incline_text(const Wall& wall) {
  if (wall.incline_deg == 0.0) return "";
  return fmt::format(", inclined {:g} degrees ({}; heights along the wall)", wall.incline_deg,
                     wall.incline_deg > 0.0 ? "overhanging" : "a slab");
}

}  // namespace

nlohmann::ordered_json generated_wall_json(const std::string& file, const Wall& wall, std::uint64_t seed,
                                           const IkResult& start, const std::string& solver) {
  nlohmann::ordered_json out;
  out["file"] = file;
  out["name"] = wall.name;
  out["seed"] = seed;
  out["holds"] = wall.hold_count();
  out["finish_height"] = wall.finish_height;
  out["incline"] = wall.incline_deg;
  out["start"] = start_holds_json(wall);
  out["start_reachable"] = start.reached;
  out["start_iterations"] = start.iterations;
  out["start_solver"] = solver;
  return out;
}

std::string generated_wall_text(const std::string& file, const Wall& wall, const IkResult& start,
                                const std::string& solver) {
  return fmt::format("wrote {}: '{}', {} holds, finish height {} m{}\n", file, printable(wall.name), wall.hold_count(),
                     wall.finish_height, incline_text(wall)) +
         fmt::format("start configuration ({}): ", start_holds_text(wall)) +
         (start.reached ? fmt::format("reachable ({} solver, {})\n", solver, counted(start.iterations, "iteration"))
                        : std::string("NOT reachable\n"));
}

nlohmann::ordered_json wall_summary_json(const std::string& file, const Wall& wall, const IkResult& start,
                                         const std::optional<PlacedGrid>& grid) {
  nlohmann::ordered_json out;
  out["file"] = file;
  out["name"] = wall.name;
  out["holds"] = wall.hold_count();
  out["finish_height"] = wall.finish_height;
  out["incline"] = wall.incline_deg;
  out["start"] = start_holds_json(wall);
  out["start_reachable"] = start.reached;
  out["start_iterations"] = start.iterations;
  if (grid) {
    nlohmann::ordered_json g;
    g["limb"] = enum_name(grid->limb);
    g["origin"] = {grid->placement.origin.x(), grid->placement.origin.y()};
    g["hold_tiles"] = nlohmann::json::array();
    for (const Hold& h : wall.holds) {
      g["hold_tiles"].push_back({{"id", h.id}, {"tile", grid->placement.tile_of(h.position)}});
    }
    g["tile_holds"] = nlohmann::json::array();
    for (int tile = 0; tile < grid->parameters.tile_count(); ++tile) {
      const int hold = hold_in_tile(wall, grid->placement, tile);
      g["tile_holds"].push_back({{"tile", tile}, {"id", hold >= 0 ? wall.holds[hold].id : 0}});
    }
    out["grid"] = g;
  }
  return out;
}

std::string wall_summary_text(const std::string& file, const Wall& wall, const IkResult& start,
                              const std::optional<PlacedGrid>& grid) {
  Eigen::Vector3d low = wall.holds[0].position, high = low;
  for (const Hold& h : wall.holds) {
    low = low.cwiseMin(h.position);
    high = high.cwiseMax(h.position);
  }
  std::string out =
      fmt::format("'{}' ({}): {} holds, y from {:.2f} to {:.2f} m, z from {:.2f} to {:.2f} m\n", printable(wall.name),
                  file, wall.hold_count(), low.y(), high.y(), low.z(), high.z()) +
      fmt::format("finish height {} m{}; start configuration: {} ({})\n", wall.finish_height, incline_text(wall),
                  start_holds_text(wall), start.reached ? "reachable" : "NOT reachable");
  if (grid) {
    out += "grid tiles -> holds (tile: hold id):";
    for (int tile = 0; tile < grid->parameters.tile_count(); ++tile) {
      const int hold = hold_in_tile(wall, grid->placement, tile);
      if (hold >= 0) out += fmt::format(" {}:{}", tile, wall.holds[hold].id);
    }
    out += '\n';
  }
  return out;
}

}  // namespace crux
