#pragma once
// crux export's output besides the file it writes: what the MuJoCo model holds, as JSON
// or one line of text.

#include <string>

#include <nlohmann/json.hpp>

#include "body/body_model.hpp"
#include "wall/wall.hpp"

namespace crux {

// What crux export --mjcf wrote: the file, the body (its mass, its joints and motors),
// the wall (its name, incline and holds).
struct MjcfExport {
  std::string file;
  std::string body;
  double mass_kg = 0.0;
  int joints = 0;  // the revolute joints, each with its motor; the root is free
  std::string wall;
  double incline_deg = 0.0;
  int holds = 0;
};

MjcfExport describe_mjcf_export(const std::string& file, const BodyModel& model, const Wall& wall);
nlohmann::ordered_json mjcf_export_json(const MjcfExport& written);
// "wrote FILE: crux_human (68.0 kg, 32 motors, free root) on random wall, seed 1 (36 holds, 0 degrees)"
std::string mjcf_export_text(const MjcfExport& written);

}  // namespace crux
