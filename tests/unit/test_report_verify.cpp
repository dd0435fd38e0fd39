// The report's verify step (tests/report/verify_report.sh) must fail the build when a figure
// or table the report references is missing or empty.  Running the whole report here would
// be too slow, so the script is pointed at a small temporary paper directory.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include "../temp_dir.hpp"

namespace fs = std::filesystem;

namespace {

struct TempReport {
  TempDir tmp{"gpm_verify_"};
  fs::path root = tmp.dir;
  TempReport() {
    fs::create_directories(root / "paper");
    fs::create_directories(root / "figures/out");
    fs::create_directories(root / "data");
    std::ofstream(root / "paper/10-x.md")
        << "# x\n\n![A caption spread\nover two lines](figures/out/a.svg)\n\n"
        << "```{.tsv file=\"t.tsv\" columns=\"a\"}\n```\n";
    std::ofstream(root / "figures/out/a.svg") << "<svg><path d='M0 0L1 1'/></svg>\n";
    std::ofstream(root / "data/t.tsv") << "# program = x\na\n1\n";
  }
  // Exit status of the script on this directory; its messages go to `log`.
  int verify() const {
    const std::string cmd = std::string("sh ") + GPM_SOURCE_DIR + "/tests/report/verify_report.sh " +
                            (root / "paper").string() + " " + (root / "data").string() + " " +
                            root.string() + " > " + (root / "log").string() + " 2>&1";
    const int rc = std::system(cmd.c_str());
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  }
  std::string log() const {
    std::ifstream in(root / "log");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
};

}  // namespace

TEST_CASE("verify_report passes a complete report and names what is missing", "[report]") {
  TempReport r;
  REQUIRE(r.verify() == 0);

  SECTION("missing figure") {
    fs::remove(r.root / "figures/out/a.svg");
    CHECK(r.verify() == 1);
    CHECK(r.log().find("figure missing: figures/out/a.svg") != std::string::npos);
  }
  SECTION("empty figure") {
    std::ofstream(r.root / "figures/out/a.svg", std::ios::trunc);
    CHECK(r.verify() == 1);
    CHECK(r.log().find("figure empty") != std::string::npos);
  }
  SECTION("SVG that draws nothing") {
    std::ofstream(r.root / "figures/out/a.svg", std::ios::trunc) << "<svg></svg>\n";
    CHECK(r.verify() == 1);
    CHECK(r.log().find("draws nothing") != std::string::npos);
  }
  SECTION("missing data table") {
    fs::remove(r.root / "data/t.tsv");
    CHECK(r.verify() == 1);
    CHECK(r.log().find("data table missing") != std::string::npos);
  }
}
