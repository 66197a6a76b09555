// `crowdsim-bench render` and `report` end to end: files written, and bad arguments rejected
// with the value and the valid range or choices (exit status 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <utility>

#include "shell.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

using testing::Shell;

std::string Exe() { return (testing::BinaryDir() / "bin" / "crowdsim-bench").string(); }
std::string Quick() { return (testing::SourceDir() / "suites" / "quick.yaml").string(); }

TEST(RenderCli, WritesEveryStillFormatAndAGif) {
  TempDir tmp;
  for (const char* ext : {"svg", "png", "pdf"}) {
    const fs::path out = tmp.path() / (std::string("e.") + ext);
    auto [rc, text] = Shell(Exe() + " render " + Quick() +
                            " --row orca --episode 0 --compare 1 --out " + out.string());
    EXPECT_EQ(rc, 0) << text;
    EXPECT_GT(fs::file_size(out), 1000u) << ext;
  }
  const fs::path gif = tmp.path() / "e.gif";
  auto [rc, text] = Shell(Exe() + " render " + Quick() +
                          " --row 2 --episode 0 --animate --speed 4 --out " + gif.string());
  EXPECT_EQ(rc, 0) << text;
  EXPECT_GT(fs::file_size(gif), 1000u);
  // Twice the same command, twice the same SVG bytes.
  const fs::path again = tmp.path() / "again.svg";
  Shell(Exe() + " render " + Quick() + " --row orca --episode 0 --compare 1 --out " +
        again.string());
  EXPECT_EQ(testing::ReadText(tmp.path() / "e.svg"), testing::ReadText(again));
  // Into folders that do not exist yet (created, as `run --out` creates its folder).
  const fs::path nested = tmp.path() / "new" / "sub" / "e.svg";
  auto [nrc, ntext] =
      Shell(Exe() + " render " + Quick() + " --row 1 --episode 0 --out " + nested.string());
  EXPECT_EQ(nrc, 0) << ntext;
  EXPECT_TRUE(fs::exists(nested));
}

TEST(RenderCli, BadArgumentsNameTheValueAndTheChoices) {
  TempDir tmp;
  const std::string svg = " --out " + (tmp.path() / "x.svg").string();
  const std::string base = Exe() + " render " + Quick();
  const std::pair<std::string, std::string> cases[] = {
      {" --row 3 --episode 0" + svg, "row 3 is out of range (valid: 1..2 or a label: linear orca)"},
      {" --row sarl --episode 0" + svg, "no row labelled 'sarl'"},
      {" --row 1 --episode 100" + svg, "episode 100 is out of range (valid: 0..99"},
      {" --row 1 --episode 0 --compare 7" + svg, "row 7 is out of range"},
      {" --row 1 --episode 0 --out " + (tmp.path() / "x.bmp").string(),
       "unknown output format '.bmp'"},
      {" --row 1 --episode 0 --out " + (tmp.path() / "x.gif").string(), "add --animate"},
      {" --row 1 --episode 0 --sensors-at 999" + svg,
       "--sensors-at 999 is outside the episode: valid steps are 0.."},
      {" --row 1 --episode 0 --animate --speed fast --out " + (tmp.path() / "x.gif").string(),
       "--speed must be a number in (0, 100]"},
      {" --row 1 --episode 0", "render needs --out"},
      {" --row 1 --episode 0 --out " + Quick() + "/under_a_file.svg",  // a file, not a folder
       "cannot create the folder of --out"},
  };
  for (const auto& [args, expected] : cases) {
    auto [rc, text] = Shell(base + args);
    EXPECT_EQ(rc, 2) << args << "\n" << text;
    EXPECT_NE(text.find(expected), std::string::npos) << args << "\n" << text;
  }
  EXPECT_FALSE(fs::exists(tmp.path() / "x.svg"));
}

TEST(ReportCli, WritesTheReportAndRejectsBadFolders) {
  TempDir tmp;
  const fs::path results = tmp.path() / "quick";
  auto [rrc, rtext] =
      Shell(Exe() + " run " + Quick() + " --episodes 3 --jobs 2 --quiet --out " + results.string());
  ASSERT_EQ(rrc, 0) << rtext;
  const fs::path html = tmp.path() / "report.html";
  auto [rc, text] = Shell(Exe() + " report " + results.string() + " --out " + html.string());
  EXPECT_EQ(rc, 0) << text;
  EXPECT_NE(testing::ReadText(html).find("<h1>quick</h1>"), std::string::npos);

  auto [mrc, mtext] =
      Shell(Exe() + " report " + (tmp.path() / "missing").string() + " --out " + html.string());
  EXPECT_EQ(mrc, 2) << mtext;
  EXPECT_NE(mtext.find("results folder '" + (tmp.path() / "missing").string() + "' does not exist"),
            std::string::npos)
      << mtext;
  // A file given for the folder (the suite, a table.md) was said not to exist.
  auto [src, stext] = Shell(Exe() + " report " + Quick() + " --out " + html.string());
  EXPECT_EQ(src, 2) << stext;
  EXPECT_NE(stext.find("results folder '" + Quick() + "' is a file, not a folder"),
            std::string::npos)
      << stext;
  auto [erc, etext] = Shell(Exe() + " report " + tmp.path().string() + " --out " + html.string());
  EXPECT_EQ(erc, 2) << etext;
  EXPECT_NE(etext.find("has no manifest.json"), std::string::npos) << etext;
  auto [frc, ftext] =
      Shell(Exe() + " report " + results.string() + " --out " + (tmp.path() / "r.pdf").string());
  EXPECT_EQ(frc, 2) << ftext;
  EXPECT_NE(ftext.find("--out must end in .html"), std::string::npos) << ftext;
}

// The page's warnings (here: the suite edited since the run, so the figures replay another
// configuration than the table's) were on the page only; `report` said "wrote" and nothing else.
TEST(ReportCli, ThePagesWarningsAreSaidOnTheCommandLine) {
  TempDir tmp;
  const fs::path suite = tmp.path() / "quick.yaml";
  fs::copy_file(Quick(), suite);
  const fs::path results = tmp.path() / "quick";
  auto [rrc, rtext] = Shell(Exe() + " run " + suite.string() +
                            " --episodes 2 --jobs 2 --quiet --out " + results.string());
  ASSERT_EQ(rrc, 0) << rtext;
  const fs::path html = tmp.path() / "report.html";
  auto [rc, text] = Shell(Exe() + " report " + results.string() + " --out " + html.string());
  EXPECT_EQ(rc, 0) << text;
  EXPECT_EQ(text.find("warning:"), std::string::npos) << text;
  std::string edited = testing::ReadText(suite);
  edited.replace(edited.find("seed: "), 6, "seed: 1");
  std::ofstream(suite, std::ios::trunc) << edited;
  auto [erc, etext] = Shell(Exe() + " report " + results.string() + " --out " + html.string());
  EXPECT_EQ(erc, 0) << etext;
  EXPECT_NE(etext.find("warning: The suite file changed since this run (config hash "),
            std::string::npos)
      << etext;
  EXPECT_NE(testing::ReadText(html).find("The suite file changed since this run"),
            std::string::npos);
}

TEST(ReportCli, AGarbageEpisodesCsvFailsAndDamagedLinesAreShown) {
  TempDir tmp;
  const fs::path results = tmp.path() / "quick";
  auto [rrc, rtext] =
      Shell(Exe() + " run " + Quick() + " --episodes 3 --jobs 2 --quiet --out " + results.string());
  ASSERT_EQ(rrc, 0) << rtext;
  const fs::path csv = results / "episodes.csv";
  std::string text = testing::ReadText(csv);

  // One damaged line among readable ones: the page says so.
  const size_t second = text.find("\nlinear,1,");
  ASSERT_NE(second, std::string::npos) << text;
  std::ofstream(csv, std::ios::trunc) << text.substr(0, second + 1) + "linear,1,oops\n" +
                                             text.substr(text.find('\n', second + 1) + 1);
  const fs::path html = tmp.path() / "report.html";
  auto [rc, out] = Shell(Exe() + " report " + results.string() + " --out " + html.string());
  EXPECT_EQ(rc, 0) << out;
  const std::string header = text.substr(0, text.find('\n'));
  const auto columns = std::count(header.begin(), header.end(), ',') + 1;
  EXPECT_NE(testing::ReadText(html).find(
                "1 damaged line(s) of episodes.csv were skipped (the first: " + csv.string() +
                ":3: it has 3 field(s), expected " + std::to_string(columns) + ")"),
            std::string::npos);

  // Garbage: an error naming the file, the line and the fix, and no page.
  std::ofstream(csv, std::ios::trunc) << "garbage\nmore garbage, x\n";
  const fs::path none = tmp.path() / "none.html";
  auto [grc, gout] = Shell(Exe() + " report " + results.string() + " --out " + none.string());
  EXPECT_NE(grc, 0) << gout;
  EXPECT_NE(gout.find(csv.string() + ":1: the header is 'garbage'"), std::string::npos) << gout;
  EXPECT_NE(gout.find("--fresh"), std::string::npos) << gout;
  EXPECT_FALSE(fs::exists(none));
}

}  // namespace
}  // namespace crowdsim
