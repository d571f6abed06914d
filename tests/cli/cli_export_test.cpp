// crux export end to end.

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/repository_docs.hpp"
#include "support/run_crux.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

using testing::run_crux;

std::filesystem::path export_scratch(const std::string& name) {
  const auto dir = testing::test_folder() / "export-cli";
  std::filesystem::create_directories(dir);
  return dir / name;
}

// The file loads in MuJoCo as written, from its own path, with no other file.
TEST(CliExport, TheMjcfLoadsInMujocoAsWrittenAndItsKeysAreTheDocumentedOnes) {
  const auto file = export_scratch("climber.xml");
  const auto outcome = run_crux("export --mjcf --wall-seed 3 --wall-incline 20 --json -o " + file.string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto json = nlohmann::ordered_json::parse(outcome.out);
  std::vector<std::string> printed;
  for (const auto& [key, value] : json.items()) printed.push_back(key);
  EXPECT_EQ(printed, testing::documented_keys(testing::repository_file("docs/OUTPUTS.md"), "## `crux export --mjcf`"));
  EXPECT_EQ(json["incline_deg"], 20.0);
  char error[1000] = "";
  mjModel* model = mj_loadXML(file.c_str(), nullptr, error, sizeof error);
  ASSERT_NE(model, nullptr) << error;
  EXPECT_EQ(model->nu, json["motors"].get<int>());
  EXPECT_NEAR(mj_getTotalmass(model), json["mass_kg"].get<double>(), 1e-6);
  mj_deleteModel(model);
  const auto text = run_crux("export --mjcf --wall-seed 3 --wall-incline 20 -o " + file.string());
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_EQ(text.out.rfind("wrote " + file.string() + ": ", 0), 0u) << text.out;
}

TEST(CliExport, BadInputIsOneLineAndExitCode2AndWritesNothing) {
  const auto file = export_scratch("refused.xml");
  for (const std::string& arguments : {std::string("export --wall-seed 3 -o ") + file.string(),  // no format
                                       std::string("export --mjcf --wall-seed 3"),               // no file
                                       // Rows of 1.5 m: the hands' start row is 4.5 m above the feet.
                                       "export --mjcf --wall-seed 4 --wall-tile-height 1.5 -o " + file.string(),
                                       "export --mjcf --wall-file /nonexistent/wall.json -o " + file.string(),
                                       "export --mjcf --wall-seed 3 --physics-friction nan -o " + file.string()}) {
    const auto outcome = run_crux(arguments);
    EXPECT_EQ(outcome.exit_code, 2) << arguments << "\n" << outcome.err;
    EXPECT_EQ(testing::count_lines(outcome.err), 1) << arguments << "\n" << outcome.err;
    EXPECT_FALSE(std::filesystem::exists(file)) << arguments;
  }
}

}  // namespace
}  // namespace crux
