// Walls (random, files, holds as arrays), the geometric filter and the possible actions
// of a configuration, and the moving grid.

#include <vector>

#include <fmt/format.h>

#include "agent_space/agent_descriptor.hpp"
#include "agent_space/moving_grid.hpp"
#include "bindings.hpp"
#include "common/input_error.hpp"
#include "configurations/geometric_filter.hpp"
#include "configurations/possible_actions.hpp"
#include "configurations/reachability.hpp"
#include "conversions.hpp"
#include "python_config.hpp"
#include "wall/random_wall.hpp"
#include "wall/wall_file.hpp"

namespace crux::python {

namespace {

const ParameterSet kWallKeys{{"wall"}, {"wall.file", "wall.seed", "wall.name", "wall.count"}};

HoldConfiguration three_configuration_from(const py::handle& holds, const Wall& wall) {
  const HoldConfiguration c = configuration_from(holds, wall, "configuration");
  if (c.free_count() != 1) throw InputError("configuration", "must have exactly one free limb (-1)");
  return c;
}

// Wall, with its constructors, file round trip and holds as numpy arrays.
void bind_wall_type(py::module_& m) {
  py::class_<Wall>(m, "Wall", "A climbing wall: hold spheres, the start configuration and the finishing height")
      .def_static(
          "random",
          [](const py::handle& seed, const py::handle& config) {
            return generate_random_wall(uint64_from(seed, "seed"),
                                        config_from_python(config, kWallKeys, "Wall.random").settings.walls);
          },
          py::arg("seed"), py::arg("config") = py::none(),
          "The random wall of a seed (section III-A); config takes the wall.* keys (columns, rows, sigma, ...)")
      .def_static(
          "load", [](const py::handle& path) { return load_wall(path_from(path)); }, py::arg("path"))
      .def_static("from_json", &parse_wall, py::arg("text"), py::arg("source") = "<string>")
      .def(
          "save", [](const Wall& wall, const py::handle& path) { save_wall(path_from(path), wall); }, py::arg("path"))
      .def("to_json", &wall_to_json)
      // As its wall file (exact: the file's numbers round-trip), so that copies and other
      // processes get the same wall: gymnasium.make deep-copies its arguments.
      .def(py::pickle([](const Wall& wall) { return wall_to_json(wall); },
                      [](const std::string& json) { return parse_wall(json, "<pickled wall>"); }))
      .def_readwrite("name", &Wall::name)
      .def_readonly("finish_height", &Wall::finish_height)
      .def_property_readonly("hold_count", &Wall::hold_count)
      .def_property_readonly("hold_ids",
                             [](const Wall& wall) {
                               py::array_t<int> out(wall.hold_count());
                               for (int i = 0; i < wall.hold_count(); ++i) out.mutable_at(i) = wall.holds[i].id;
                               return out;
                             })
      .def_property_readonly(
          "positions",
          [](const Wall& wall) {
            py::array_t<double> out({wall.hold_count(), 3});
            for (int i = 0; i < wall.hold_count(); ++i) {
              for (int c = 0; c < 3; ++c) out.mutable_at(i, c) = wall.holds[i].position[c];
            }
            return out;
          },
          "(N, 3) hold centres, in the order of hold indices")
      .def_property_readonly("radii",
                             [](const Wall& wall) {
                               py::array_t<double> out(wall.hold_count());
                               for (int i = 0; i < wall.hold_count(); ++i) out.mutable_at(i) = wall.holds[i].radius;
                               return out;
                             })
      .def_property_readonly(
          "start", [](const Wall& wall) { return to_array(HoldConfiguration{wall.start}); },
          "hold indices of the start configuration, limb order")
      .def("index_of", &Wall::index_of, py::arg("id"), "the index of the hold with this id, or -1")
      .def("__repr__", [](const Wall& wall) {
        return fmt::format("<crux.Wall '{}', {} holds, finish at {} m>", wall.name, wall.hold_count(),
                           wall.finish_height);
      });
}

// The geometric filter and the possible actions it leaves a 3-configuration.
void bind_geometric_filter(py::module_& m) {
  m.def(
      "passes_filter",
      [](const Wall& wall, const py::handle& configuration, const py::handle& config) {
        const ExperimentConfig c = config_from_python(config, kFilterKeys, "passes_filter");
        return passes_filter(wall, configuration_from(configuration, wall, "configuration"),
                             c.settings.learning.climbing.filter);
      },
      py::arg("wall"), py::arg("configuration"), py::arg("config") = py::none(),
      "Whether a configuration (4 hold indices, -1 free) passes the geometric filter (section III-C)");

  m.def(
      "possible_actions",
      [](const Wall& wall, const py::handle& configuration, const py::handle& config) {
        const ExperimentConfig c = config_from_python(config, kFilterKeys, "possible_actions");
        std::vector<int> out(wall.hold_count());
        const int count = possible_actions(wall, three_configuration_from(configuration, wall),
                                           c.settings.learning.climbing.filter, out);
        return py::array_t<int>(count, out.data());
      },
      py::arg("wall"), py::arg("configuration"), py::arg("config") = py::none(),
      "The holds (indices, ascending) the free limb of a 3-configuration may take under the geometric filter");
}

// The moving grid, its placement on a free limb, and the codes of the two state spaces.
void bind_moving_grid(py::module_& m) {
  py::class_<GridPlacement>(m, "GridPlacement", "The moving grid placed on a free limb (section III-D, Fig. 2a)")
      .def_property_readonly(
          "origin", [](const GridPlacement& p) { return to_array(Eigen::Vector3d(0.0, p.origin.x(), p.origin.y())); },
          "(0, y, z) of the corner of tile 0")
      .def_readonly("columns", &GridPlacement::columns)
      .def_readonly("rows", &GridPlacement::rows)
      .def_readonly("tile_width", &GridPlacement::tile_width)
      .def_readonly("tile_height", &GridPlacement::tile_height)
      .def_readonly("anchor_tile", &GridPlacement::anchor_tile)
      .def(
          "tile_of",
          [](const GridPlacement& p, const py::handle& point) { return p.tile_of(point_from(point, "point")); },
          py::arg("point"), "the tile holding a point, or -1 outside the grid")
      .def(
          "tile_centre",
          [](const GridPlacement& p, const py::handle& tile) {
            return to_array(p.tile_centre(static_cast<int>(integer_from(tile, 0, p.columns * p.rows - 1, "tile"))));
          },
          py::arg("tile"));

  m.def(
      "place_grid",
      [](const py::handle& free_limb, const py::handle& position, const py::handle& config) {
        const ExperimentConfig c = config_from_python(config, kGridKeys, "place_grid");
        return place_grid(c.settings.learning.climbing.grid, limb_from(free_limb), point_from(position, "position"));
      },
      py::arg("free_limb"), py::arg("position"), py::arg("config") = py::none(),
      "The grid placed so that the free limb's anchor tile is centred on `position`; config takes grid.*");

  m.def(
      "hold_in_tile",
      [](const Wall& wall, const GridPlacement& placement, const py::handle& tile) {
        return hold_in_tile(wall, placement,
                            static_cast<int>(integer_from(tile, 0, placement.columns * placement.rows - 1, "tile")));
      },
      py::arg("wall"), py::arg("placement"), py::arg("tile"),
      "Grid -> wall: the hold nearest the tile's centre among those in it, or -1");

  m.def(
      "agent_state",
      [](const Wall& wall, const py::handle& configuration, const GridPlacement& placement, const py::handle& config) {
        const ExperimentConfig c = config_from_python(config, kGridKeys, "agent_state");
        return encode(describe_state(wall, three_configuration_from(configuration, wall), placement),
                      c.settings.learning.climbing.grid);
      },
      py::arg("wall"), py::arg("configuration"), py::arg("placement"), py::arg("config") = py::none(),
      "The agent-space state code of a 3-configuration with the grid placed on its free limb");

  m.def(
      "wall_state",
      [](const Wall& wall, const py::handle& configuration) {
        return encode(configuration_from(configuration, wall, "configuration"), wall.hold_count());
      },
      py::arg("wall"), py::arg("configuration"), "The problem-space code of a configuration");
}

}  // namespace

void bind_wall(py::module_& m) {
  bind_wall_type(m);
  bind_geometric_filter(m);
  bind_moving_grid(m);
}

}  // namespace crux::python
