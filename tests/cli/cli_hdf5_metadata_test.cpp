// What is checked against what: every HDF5 file the tool writes (sweep beam, path with and without
// a chain file, validate, bench and its checkpoint, dynamics, mechanism analyze) is written by the
// built binary on small inputs and read back with the plain HDF5 C API:
//  - a walk over EVERY object (H5Lvisit) finds each dataset with a non-empty `units` and a
//    non-empty one-line `description` attribute;
//  - the root says where the file came from: tool_version and git_commit equal what the same
//    binary prints for --version (an independent route to the version), command_line names the
//    subcommand and the output file, creation_time is ISO 8601 UTC within 10 minutes of the test's
//    clock (the run takes seconds; the margin only absorbs clock granularity and slow machines);
//  - every value that occurs in a code dataset (status, within_validity, reference_source) has a
//    line "<dataset> <value>: ..." in the root attribute status_meanings;
//  - the renamed attributes: one spelling (tool_version, load_ratio_n, integer booleans).
#include <gtest/gtest.h>

#include <chrono>
#include <ctime>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

// Datasets whose integers are codes with documented meanings.
const std::set<std::string> kCodeDatasets = {"status", "within_validity", "reference_source"};

struct Walk {
  std::vector<std::string> datasets;  // full paths, "/a/b"
};

herr_t collect(hid_t root, const char* name, const H5L_info_t*, void* data) {
  const hid_t object = H5Oopen(root, name, H5P_DEFAULT);
  if (object < 0) return -1;
  if (H5Iget_type(object) == H5I_DATASET) {
    static_cast<Walk*>(data)->datasets.push_back(std::string("/") + name);
  }
  H5Oclose(object);
  return 0;
}

std::vector<std::string> all_datasets(hid_t file) {
  Walk walk;
  EXPECT_GE(H5Lvisit(file, H5_INDEX_NAME, H5_ITER_INC, collect, &walk), 0);
  return walk.datasets;
}

// "flexure 0.4.0 (git commit abc123)" -> {"0.4.0", "abc123"}.
std::pair<std::string, std::string> binary_version() {
  const CommandResult r = run_flexure("--version");
  std::smatch m;
  const std::regex pattern(R"(flexure (\S+) \(git commit (\S+)\))");
  EXPECT_TRUE(std::regex_search(r.out, m, pattern)) << r.out;
  return {m[1], m[2]};
}

// Checks one written file; `subcommand` and `out` (default: the file's name) must occur in its
// command line.
void check_file(const std::filesystem::path& path,
                const std::string& subcommand,
                std::string out = "") {
  if (out.empty()) out = path.filename().string();
  SCOPED_TRACE(path.filename().string());
  const hid_t file = open_read_only(path);
  ASSERT_GE(file, 0) << "not readable as HDF5";
  const std::vector<std::string> datasets = all_datasets(file);
  EXPECT_FALSE(datasets.empty());
  const std::string meanings = read_string_attribute(file, "/", "status_meanings");
  EXPECT_NE(meanings, "<missing>");
  for (const std::string& d : datasets) {
    const std::string units = read_string_attribute(file, d.c_str(), "units");
    const std::string description = read_string_attribute(file, d.c_str(), "description");
    EXPECT_FALSE(units.empty() || units == "<missing>" || units == "<unreadable>") << d;
    EXPECT_FALSE(description.empty() || description == "<missing>" || description == "<unreadable>")
        << d;
    EXPECT_EQ(description.find('\n'), std::string::npos) << d << ": " << description;
    const std::string name = d.substr(d.rfind('/') + 1);
    if (kCodeDatasets.count(name) == 0) continue;
    const std::vector<int> codes = read_ints(file, d.c_str());
    for (int value : std::set<int>(codes.begin(), codes.end())) {
      const std::string line = name + " " + std::to_string(value) + ": ";
      const bool first = meanings.rfind(line, 0) == 0;
      EXPECT_TRUE(first || meanings.find("\n" + line) != std::string::npos)
          << d << " holds " << value << " but status_meanings has no line for it:\n"
          << meanings;
    }
  }

  const auto [version, commit] = binary_version();
  EXPECT_EQ(read_string_attribute(file, "/", "tool"), "flexure");
  EXPECT_EQ(read_string_attribute(file, "/", "tool_version"), version);
  EXPECT_EQ(read_string_attribute(file, "/", "git_commit"), commit);
  const std::string command = read_string_attribute(file, "/", "command_line");
  EXPECT_NE(command.find(" " + subcommand + " "), std::string::npos) << command;
  EXPECT_NE(command.find(out), std::string::npos) << command;
  const std::string time = read_string_attribute(file, "/", "creation_time");
  std::tm tm{};
  const char* end = strptime(time.c_str(), "%Y-%m-%dT%H:%M:%SZ", &tm);
  ASSERT_TRUE(end != nullptr && *end == '\0') << time;
  const double age = std::difftime(std::time(nullptr), timegm(&tm));
  EXPECT_LT(std::abs(age), 600.0) << time;
  // Old spellings are gone.
  EXPECT_EQ(read_string_attribute(file, "/", "version"), "<missing>");
  EXPECT_EQ(read_string_attribute(file, "/", "date"), "<missing>");
  H5Fclose(file);
}

TEST(CliHdf5Metadata, SweepFilesAreSelfDescribing) {
  ScratchDir dir;
  // PRBM from alpha2 = 2 to 8: within and outside its validity limit (codes 1 and 0).
  CommandResult r =
      run_flexure("sweep beam --alpha2 2:8:4 --method prbm --out 'prbm sweep.h5'", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_file(dir / "prbm sweep.h5", "sweep beam");
  r = run_flexure("sweep beam --n 0.5 --alpha2 0:3:4 --out s.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_file(dir / "s.h5", "sweep beam");
  const hid_t file = open_read_only(dir / "s.h5");
  EXPECT_EQ(read_double_attribute(file, "/", "load_ratio_n"), 0.5);
  EXPECT_TRUE(std::isnan(read_double_attribute(file, "/", "n"))) << "old spelling";
  EXPECT_EQ(read_string_attribute(file, "theta0", "units"), "rad");
  EXPECT_EQ(read_string_attribute(file, "alpha2", "units"), "1");
  H5Fclose(file);
  // The quoted file name is recorded so that the shell reads it back as one argument.
  const hid_t prbm = open_read_only(dir / "prbm sweep.h5");
  EXPECT_NE(read_string_attribute(prbm, "/", "command_line").find("--out 'prbm sweep.h5'"),
            std::string::npos);
  H5Fclose(prbm);
}

TEST(CliHdf5Metadata, PathFilesAreSelfDescribing) {
  ScratchDir dir;
  CommandResult r = run_flexure("path --alpha2 2 --out p.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_file(dir / "p.h5", "path");
  const hid_t file = open_read_only(dir / "p.h5");
  // A boolean is an integer 0/1 in every file (it was the string "true" here).
  EXPECT_EQ(read_int_attribute(file, "/", "completed"), 1);
  EXPECT_EQ(read_string_attribute(file, "tip_theta", "units"), "rad");
  H5Fclose(file);
  r = run_flexure("path --method chain --chain '" FLEXURE_SOURCE_DIR
                  "/docs/examples/two_flexures_rigid_link.toml' --out c.h5",
                  dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_file(dir / "c.h5", "path");
  const hid_t chain = open_read_only(dir / "c.h5");
  EXPECT_EQ(read_string_attribute(chain, "tip_x", "units"), "length unit of the chain file");
  H5Fclose(chain);
}

TEST(CliHdf5Metadata, ValidateFileIsSelfDescribing) {
  ScratchDir dir;
  const CommandResult r = run_flexure("validate --out v.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_file(dir / "v.h5", "validate");
}

TEST(CliHdf5Metadata, BenchFileAndCheckpointAreSelfDescribing) {
  ScratchDir dir;
  CommandResult r =
      run_flexure("bench --quick --problems cantilever_force,cfm_stroke --out b.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_file(dir / "b.h5", "bench");
  const hid_t file = open_read_only(dir / "b.h5");
  EXPECT_EQ(read_string_attribute(file, "/cfm_stroke/prbm/force", "units"), "N");
  EXPECT_EQ(read_string_attribute(file, "/cantilever_force/prbm/theta0", "units"), "rad");
  EXPECT_EQ(read_ints(file, "/cantilever_force/prbm/inside_validity").size(), 0u) << "old spelling";
  H5Fclose(file);
  r = run_flexure("bench --quick --problems tip_moment --stop-after 1 --out k.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_file(dir / "k.h5.partial", "bench", "--out k.h5");
}

TEST(CliHdf5Metadata, DynamicsFileIsSelfDescribing) {
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "dynamics --mechanism 2B-lplm --omega 0:30:3 --samples 64 --history 10 --out d.h5",
      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_file(dir / "d.h5", "dynamics");
  const hid_t file = open_read_only(dir / "d.h5");
  EXPECT_EQ(read_string_attribute(file, "omega", "units"), "rad/s");
  EXPECT_EQ(read_string_attribute(file, "/history/0/force", "units"), "N");
  H5Fclose(file);
}

TEST(CliHdf5Metadata, MechanismAnalyzeFileIsSelfDescribing) {
  ScratchDir dir;
  const CommandResult r =
      run_flexure("mechanism analyze 1A-spp --points 6 --method exact --out m.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_file(dir / "m.h5", "mechanism analyze");
}

TEST(CliHdf5Metadata, ModelsMapFileIsSelfDescribing) {
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "models map --n 0 --alpha2 1:2:2 --mu 0:0.5:2 --min-seconds 0 --out models.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  check_file(dir / "models.h5", "models map");
}

}  // namespace
}  // namespace flexure::test
