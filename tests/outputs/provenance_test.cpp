#include "outputs/provenance.hpp"

#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "common/sha256.hpp"
#include "support/repository_docs.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(Provenance, RecordsTheInputsDigestsAndTheSeed) {
  ExperimentConfig config;
  config.urdf = testing::write_temporary("provenance.urdf", testing::human_urdf_text()).string();
  config.wall_seed = 42;
  const Provenance p = record_provenance(config);
  EXPECT_EQ(p.urdf_sha256, sha256_hex(testing::human_urdf_text()));
  EXPECT_EQ(p.urdf, config.urdf) << "already absolute";
  EXPECT_EQ(p.wall_seed, 42u);
  EXPECT_TRUE(p.wall_sha256.empty());
  EXPECT_FALSE(p.crux_version.empty());
  const std::string toml = provenance_toml(p);
  EXPECT_NE(toml.find("[provenance]"), std::string::npos);
  EXPECT_NE(toml.find("urdf_sha256 = \"" + p.urdf_sha256 + "\""), std::string::npos);
  EXPECT_EQ(provenance_json(p)["wall_seed"], 42);
  EXPECT_TRUE(provenance_json(p)["wall_sha256"].is_null());
}

// README says what config.toml's [provenance] records: every key it can write, by name.
TEST(Provenance, ReadmeNamesEveryKeyConfigTomlRecords) {
  Provenance every;
  every.crux_version = every.git_commit = every.produced_by = every.urdf = every.urdf_sha256 = "x";
  every.wall_file = every.wall_sha256 = every.q_grid = every.q_grid_sha256 = "x";
  const std::string readme = testing::repository_file("README.md");
  const std::string toml = provenance_toml(every);
  std::size_t keys = 0;
  for (std::size_t at = toml.find("\n", toml.find("[provenance]")); at + 1 < toml.size();
       at = toml.find('\n', at + 1)) {
    const std::string key = toml.substr(at + 1, toml.find(" = ", at) - at - 1);
    EXPECT_NE(readme.find("`" + key + "`"), std::string::npos) << key;
    ++keys;
  }
  EXPECT_EQ(keys, 9u);
  EXPECT_EQ(readme.find("the command that ran it"), std::string::npos) << "it records the job, not the command line";
}

TEST(Provenance, AReplayWithAnotherFileIsRefusedNamingTheConfig) {
  ExperimentConfig config;
  config.urdf = testing::write_temporary("provenance_replay.urdf", testing::human_urdf_text()).string();
  const Provenance now = record_provenance(config);
  config.recorded_provenance["urdf_sha256"] = now.urdf_sha256;
  EXPECT_NO_THROW(check_recorded_provenance(config, now, "cfg.toml"));
  config.recorded_provenance["urdf_sha256"] = sha256_hex("another body");
  try {
    check_recorded_provenance(config, now, "cfg.toml");
    FAIL() << "accepted another URDF";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "cfg.toml");
    EXPECT_NE(e.problem().find("provenance.urdf_sha256"), std::string::npos) << e.what();
  }
  config.recorded_provenance.clear();
  config.recorded_provenance["q_grid_sha256"] = sha256_hex("a table");
  EXPECT_THROW(check_recorded_provenance(config, now, "cfg.toml"), InputError) << "the recorded Q_grid is missing";
}

}  // namespace
}  // namespace crux
