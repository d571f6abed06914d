#include "reports/html_report.hpp"

#include <regex>

#include <gtest/gtest.h>

#include "support/svg_check.hpp"

namespace crux {
namespace {

using testing::count_of;

ReportPage experiment_page() {
  ReportPage page;
  page.title = "crux report: <test>";
  page.summary = nlohmann::json::parse(R"({
    "format": "crux-summary", "version": 3, "kind": "experiment",
    "provenance": {"crux_version": "0.1.0", "git_commit": "abc", "urdf": "/m/crux_human.urdf"},
    "seed": 7, "wall_pairs": 6, "seeds_per_wall": 1, "iterations": 8000, "beginning_iterations": 2000, "solver": "fast",
    "table1": {"training": {"beginning": {"w_greedy": {"actions": 33.2, "success_rate": 1.0, "vertical_cm": 7.94}}}},
    "transfer_vs_control": {"jumpstart": {"description": "length of the first episode", "higher_is_better": false,
      "transfer": {"mean": 725.3}, "control": {"mean": 551.8},
      "transfer_minus_control": {"mean": 173.5, "ci95_t_over_walls": [-677.7, 1024.7],
                                 "ci95_cluster_bootstrap": [-453.7, 692.7], "p_value": 0.6227, "walls": 6},
      "iqm": {"transfer": {"value": 700.5, "low": 650, "high": 760}, "control": {"value": 540, "low": 500, "high": 590},
              "difference": {"value": 150.25, "low": -20, "high": null}},
      "probability_of_improvement": {"value": 0.375, "low": 0.25, "high": 0.5}}}
  })");
  page.figures.push_back({"Fig. 4", "lengths", "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"/>"});
  page.replay_title = "training_0";
  page.replay = {{"title", "a </script> in a name"}, {"frames", {{"count", 0}}}};
  page.style = "main { margin: 0 }";
  page.script = "window.loaded = true;";
  return page;
}

TEST(HtmlReport, ForbidsEveryRequestAndInlinesItsStyleAndScript) {
  const std::string html = html_report(experiment_page());
  EXPECT_NE(html.find("content=\"default-src 'none'; script-src 'unsafe-inline'; style-src 'unsafe-inline'"),
            std::string::npos);
  EXPECT_NE(html.find("<style>\nmain { margin: 0 }\n</style>"), std::string::npos);
  EXPECT_NE(html.find("<script>\nwindow.loaded = true;\n</script>"), std::string::npos);
  // The only URLs are SVG's namespace names, which are never fetched, and the empty icon.
  const std::regex url("(https?:|src=|href=|url\\()");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), url); it != std::sregex_iterator(); ++it) {
    const bool svg_namespace = html.compare(it->position(), 26, "http://www.w3.org/2000/svg") == 0;
    const bool empty_icon = html.compare(it->position(), 13, "href=\"data:,\"") == 0;
    EXPECT_TRUE(svg_namespace || empty_icon) << html.substr(it->position(), 40);
  }
}

TEST(HtmlReport, ReplayDataCannotCloseItsScriptElement) {
  const std::string html = html_report(experiment_page());
  const std::size_t data = html.find("<script type=\"application/json\" id=\"crux-replay-data\">");
  ASSERT_NE(data, std::string::npos);
  const std::size_t end = html.find("</script>", data);
  const std::string json = html.substr(data, end - data);
  EXPECT_NE(json.find("a \\u003c/script> in a name"), std::string::npos);
  EXPECT_EQ(json.find('<', 1), std::string::npos) << "no '<' inside the data";
  EXPECT_EQ(nlohmann::json::parse(json.substr(json.find('>') + 1))["title"], "a </script> in a name");
  EXPECT_NE(html.find("<div id=\"crux-replay\"></div>"), std::string::npos);
}

TEST(HtmlReport, TableOneShowsOursBesideThePapersAndTheStatisticsTheirIntervals) {
  const std::string html = html_report(experiment_page());
  // training, beginning, w-greedy: 7.9 cm against the paper's 7.3, 100 % against 100.
  EXPECT_NE(html.find("<td>7.9 <span class=\"paper\">(7.3)</span></td>"), std::string::npos);
  EXPECT_NE(html.find("<td>100.0 <span class=\"paper\">(100.0)</span></td>"), std::string::npos);
  EXPECT_NE(html.find("<td>33</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>174</td><td>[-678, 1.02e+03]</td><td>[-454, 693]</td><td>0.623</td><td>6</td>"),
            std::string::npos);
  EXPECT_NE(html.find("crux report: &lt;test&gt;"), std::string::npos);
  EXPECT_NE(html.find("<tr><th>jumpstart</th><td>700 [650, 760]</td><td>540 [500, 590]</td><td>+150 [-20, "
                      "&ndash;]</td><td>0.38 [0.25, 0.50]</td></tr>"),
            std::string::npos)
      << html;
}

TEST(HtmlReport, WithoutStratifiedIntervalsTheTableSaysSoRatherThanShowZeroWidths) {
  ReportPage page = experiment_page();
  auto& comparison = page.summary["transfer_vs_control"]["jumpstart"];
  for (auto* estimate : {&comparison["iqm"]["transfer"], &comparison["iqm"]["control"],
                         &comparison["iqm"]["difference"], &comparison["probability_of_improvement"]}) {
    (*estimate)["low"] = nullptr;
    (*estimate)["high"] = nullptr;
  }
  const std::string html = html_report(page);
  EXPECT_NE(html.find("<tr><th>jumpstart</th><td>700</td><td>540</td><td>+150</td><td>0.38</td></tr>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<p>No intervals: one seed per wall leaves the stratified bootstrap nothing to resample.</p>"),
            std::string::npos)
      << html;
  EXPECT_EQ(html_report(experiment_page()).find("No intervals"), std::string::npos);
}

TEST(HtmlReport, FiguresAreInlinedWithoutTheirXmlDeclaration) {
  const std::string html = html_report(experiment_page());
  EXPECT_EQ(html.find("<?xml"), std::string::npos);
  EXPECT_EQ(count_of(html, "<figure>"), 1);
  EXPECT_NE(html.find("<svg xmlns=\"http://www.w3.org/2000/svg\"/>"), std::string::npos);
}

TEST(HtmlReport, ARunPageHasNoTableOneAndNoReplayWhenThereIsNoClimb) {
  ReportPage page = experiment_page();
  page.summary["kind"] = "run";
  page.replay = nullptr;
  page.replay_reason = "the greedy policy did not reach the top within 500 actions and the run completed no episode";
  const std::string html = html_report(page);
  EXPECT_EQ(html.find("id=\"table-one\""), std::string::npos);
  EXPECT_EQ(html.find("crux-replay"), std::string::npos);
  EXPECT_NE(html.find("id=\"run\""), std::string::npos);
  EXPECT_NE(html.find("<h2>Replay</h2>\n<p>No replay: the greedy policy did not reach the top within 500 actions and "
                      "the run completed no episode.</p>"),
            std::string::npos)
      << "why there is none";
}

// The replay says which climb it shows and why: here the last episode, standing in for
// a greedy climb that does not finish.
TEST(HtmlReport, TheReplaySaysWhichClimbItShowsAndWhy) {
  ReportPage page = experiment_page();
  page.replay_title = "training_0 on 'w': the climb of episode 42";
  page.replay_reason =
      "the last completed episode (episode 42), since the greedy policy did not reach the top "
      "within 500 actions (experiment.greedy_cap)";
  const std::string html = html_report(page);
  EXPECT_NE(html.find("<h2>Replay: training_0 on &apos;w&apos;: the climb of episode 42</h2>\n<p>Replayed: the last "
                      "completed episode (episode 42), since the greedy policy did not reach the top within 500 "
                      "actions (experiment.greedy_cap).</p>"),
            std::string::npos)
      << html.substr(html.find("<section id=\"replay\">"), 400);
}

TEST(HtmlReport, TheDesignCountsAgreeWithTheirNouns) {
  ReportPage page = experiment_page();
  EXPECT_NE(html_report(page).find("<dd>6 wall pairs &times; 1 seed per wall, 8000 iterations per run, fast IK "
                                   "solver</dd>"),
            std::string::npos);
  page.summary["wall_pairs"] = 1;
  page.summary["beginning_iterations"] = 1;
  const std::string html = html_report(page);
  EXPECT_NE(html.find("<dd>1 wall pair &times; 1 seed per wall,"), std::string::npos);
  EXPECT_NE(html.find("Beginning = the first 1 iteration."), std::string::npos);
  EXPECT_NE(html.find("then over the 1 wall:"), std::string::npos);
}

}  // namespace
}  // namespace crux

namespace crux {
namespace {

PerformedSection performed_section_of(nlohmann::ordered_json replay) {
  return {"the wall's exact plan under the static model on 'w'",
          "1 of 2 moves performed; move 2 (left_hand to hold 3) failed: the body hit the wall.",
          "out/perform",
          {{"right_hand", 5, true, "", 0.5}, {"left_hand", 3, false, "the body hit the wall", 0.9}},
          std::move(replay)};
}

// A crux perform folder's page: the performed climb alone, its moves in a table and its
// replay's data under its own id.
TEST(HtmlReport, APerformFolderPageShowsThePerformedClimbAlone) {
  ReportPage page;
  page.title = "crux report: perform";
  page.performed = performed_section_of({{"performed", true}});
  page.script = "window.loaded = true;";
  const std::string html = html_report(page);
  EXPECT_EQ(html.find("id=\"table-one\""), std::string::npos);
  EXPECT_EQ(html.find("id=\"crux-replay\""), std::string::npos);
  EXPECT_NE(
      html.find("<h2>Performed in MuJoCo: the wall&apos;s exact plan under the static model on &apos;w&apos;</h2>"),
      std::string::npos);
  EXPECT_NE(html.find("<td>2</td><td>left_hand</td><td>3</td><td>failed: the body hit the wall</td><td>0.90</td>"),
            std::string::npos);
  EXPECT_EQ(count_of(html, "<div id=\"crux-performed\"></div>"), 1);
  EXPECT_EQ(count_of(html, "id=\"crux-performed-data\""), 1);
  EXPECT_EQ(count_of(html, "window.loaded = true;"), 1);
}

// README's main job: the paper's kinematic replay, then the climb performed in MuJoCo,
// each saying which it is; the script is inlined once for both.
TEST(HtmlReport, APerformedClimbBesideTheReplaySaysWhichIsWhich) {
  ReportPage page = experiment_page();
  page.performed = performed_section_of({{"performed", true}});
  const std::string html = html_report(page);
  const std::size_t replay = html.find("<section id=\"replay\">"), performed = html.find("<section id=\"performed\">");
  ASSERT_NE(replay, std::string::npos);
  ASSERT_NE(performed, std::string::npos);
  EXPECT_LT(replay, performed);
  EXPECT_NE(html.find("postures from the IK, nothing simulated"), std::string::npos);
  EXPECT_NE(html.find("Not the IK's drawing: the motion MuJoCo simulated"), std::string::npos);
  EXPECT_EQ(count_of(html, "id=\"crux-replay-data\""), 1);
  EXPECT_EQ(count_of(html, "id=\"crux-performed-data\""), 1);
  EXPECT_EQ(count_of(html, "window.loaded = true;"), 1);
  page.performed->replay = nullptr;
  EXPECT_EQ(html_report(page).find("crux-performed"), std::string::npos) << "nothing performed, nothing to play";
}

}  // namespace
}  // namespace crux
