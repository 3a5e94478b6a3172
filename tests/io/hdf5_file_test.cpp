// What is checked against what: io::AtomicHdf5File / Hdf5Group write datasets, groups and
// attributes that are read back with the plain HDF5 C API and compared bit for bit with the
// values written; the atomic-write contract (temporary next to the target, renamed on commit,
// removed when not committed or after a failed write) is checked by listing the directory; an
// unwritable target fails before anything is written, naming the path. Every dataset carries the
// units and description it was written with, a dataset without them is refused, and commit()
// refuses a file without the provenance of io/platform/provenance.h (checked against the literal
// strings written and against flexure/version.h); shell_quote against hand-quoted strings.
#include "flexure/io/platform/hdf5_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <ctime>
#include <fstream>
#include <limits>
#include <random>

#include "flexure/io/platform/provenance.h"
#include "flexure/version.h"
#include "tests/support/cli_test_support.h"

namespace flexure::io {
namespace {

using test::ScratchDir;

TEST(AtomicHdf5File, WritesDatasetsGroupsAndAttributesThatReadBackExactly) {
  ScratchDir dir;
  const auto path = dir / "data.h5";
  const std::vector<double> doubles = {0.0, -1.5, 3.0870030, 1e-300, std::nan("")};
  const std::vector<int> ints = {0, 1, -7, 2147483647};
  const std::vector<std::string> strings = {"elliptic", "", "theta0 = 1 rad (57.3\xC2\xB0)"};
  {
    AtomicHdf5File file(path.string());
    file.root().write_dataset("x", std::span<const double>(doubles), "1", "test data");
    file.root().write_dataset("status", std::span<const int>(ints), "1", "test data");
    file.root().write_dataset("names", strings, "text", "test strings");
    file.root().write_dataset("empty", std::span<const double>(), "1", "test data");
    file.root().set_attribute("method", "elliptic");
    file.root().set_attribute("n", 2.5);
    file.root().set_attribute("count", std::int64_t{1000000});
    Hdf5Group group = file.root().create_group("problem");
    group.set_attribute("source", std::string("Howell eq. 2.90"));
    group.set_attribute("mu", -0.25);
    group.write_dataset("b_over_l", std::span<const double>(doubles).first(2), "1", "test data");
    Hdf5Group nested = group.create_group("inner");
    nested.write_dataset("status", std::span<const int>(ints).first(1), "1", "test data");
    write_provenance(file.root(), {});
    file.commit();
    EXPECT_TRUE(file.committed());
  }
  hid_t file = test::open_read_only(path);
  ASSERT_GE(file, 0) << "committed file is not readable";
  const std::vector<double> x = test::read_doubles(file, "x");
  ASSERT_EQ(x.size(), doubles.size());
  for (std::size_t i = 0; i + 1 < x.size(); ++i) EXPECT_EQ(x[i], doubles[i]) << i;
  EXPECT_TRUE(std::isnan(x.back())) << "NaN must survive the round trip (it means no solution)";
  EXPECT_EQ(test::read_ints(file, "status"), ints);
  EXPECT_EQ(test::read_strings(file, "names"), strings);
  EXPECT_TRUE(test::read_doubles(file, "empty").empty());
  EXPECT_EQ(test::read_string_attribute(file, "/", "method"), "elliptic");
  EXPECT_EQ(test::read_double_attribute(file, "/", "n"), 2.5);
  EXPECT_EQ(test::read_int_attribute(file, "/", "count"), 1000000);
  EXPECT_EQ(test::read_string_attribute(file, "/problem", "source"), "Howell eq. 2.90");
  EXPECT_EQ(test::read_double_attribute(file, "/problem", "mu"), -0.25);
  EXPECT_EQ(test::read_doubles(file, "/problem/b_over_l"),
            (std::vector<double>{doubles[0], doubles[1]}));
  EXPECT_EQ(test::read_ints(file, "/problem/inner/status"), std::vector<int>{0});
  H5Fclose(file);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"data.h5"}) << "temporary left behind";
}

TEST(AtomicHdf5File, WritesUnderATemporaryNameInTheSameDirectoryUntilCommit) {
  ScratchDir dir;
  const auto path = dir / "out.h5";
  AtomicHdf5File file(path.string());
  EXPECT_EQ(std::filesystem::path(file.temp_path()).parent_path(), path.parent_path())
      << "rename() is only atomic within one file system";
  EXPECT_TRUE(std::filesystem::exists(file.temp_path()));
  EXPECT_FALSE(std::filesystem::exists(path)) << "the target must not appear before commit";
  file.root().write_dataset(
      "x", std::span<const double>(std::vector<double>{1.0}), "1", "test data");
  write_provenance(file.root(), {});
  file.commit();
  EXPECT_TRUE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(file.temp_path()));
}

TEST(AtomicHdf5File, DestroyedWithoutCommitLeavesNoFileBehind) {
  ScratchDir dir;
  {
    AtomicHdf5File file((dir / "never.h5").string());
    file.root().write_dataset(
        "x", std::span<const double>(std::vector<double>{1.0, 2.0}), "1", "test data");
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicHdf5File, FailedWriteThrowsNamingTheObjectAndLeavesNoFile) {
  ScratchDir dir;
  const auto path = dir / "broken.h5";
  try {
    AtomicHdf5File file(path.string());
    file.root().write_dataset(
        "x", std::span<const double>(std::vector<double>{1.0}), "1", "test data");
    // A second dataset with the same name is refused by HDF5.
    file.root().write_dataset(
        "x", std::span<const double>(std::vector<double>{2.0}), "1", "test data");
    FAIL() << "duplicate dataset was accepted";
  } catch (const Hdf5Error& e) {
    EXPECT_NE(std::string(e.what()).find("'/x'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(dir.entries().empty()) << "a failed write must leave nothing behind";
}

TEST(AtomicHdf5File, DuplicateAttributeAndGroupAreErrors) {
  ScratchDir dir;
  AtomicHdf5File file((dir / "dup.h5").string());
  file.root().set_attribute("n", 1.0);
  EXPECT_THROW(file.root().set_attribute("n", 2.0), Hdf5Error);
  Hdf5Group group = file.root().create_group("g");
  EXPECT_THROW(file.root().create_group("g"), Hdf5Error);
  EXPECT_THROW(file.root().create_group("a/b"), Hdf5Error);
}

TEST(AtomicHdf5File, CommitReplacesAnExistingFileWhole) {
  ScratchDir dir;
  const auto path = dir / "old.h5";
  std::ofstream(path) << "not an HDF5 file";
  {
    AtomicHdf5File file(path.string());
    file.root().write_dataset(
        "x", std::span<const double>(std::vector<double>{4.0}), "1", "test data");
    write_provenance(file.root(), {});
    file.commit();
  }
  hid_t file = test::open_read_only(path);
  ASSERT_GE(file, 0);
  EXPECT_EQ(test::read_doubles(file, "x"), std::vector<double>{4.0});
  H5Fclose(file);
}

TEST(AtomicHdf5File, MissingDirectoryIsAClearErrorBeforeWriting) {
  try {
    AtomicHdf5File file("/nonexistent/dir/x.h5");
    FAIL() << "no error for a missing directory";
  } catch (const Hdf5Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("/nonexistent/dir/x.h5"), std::string::npos) << message;
    EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  }
}

TEST(AtomicHdf5File, ParentThatIsAFileOrATargetThatIsADirectoryIsAnError) {
  ScratchDir dir;
  std::ofstream(dir / "plain") << "x";
  EXPECT_THROW(AtomicHdf5File((dir / "plain" / "x.h5").string()), Hdf5Error);
  std::filesystem::create_directory(dir / "sub");
  EXPECT_THROW(AtomicHdf5File((dir / "sub").string()), Hdf5Error);
}

TEST(AtomicHdf5File, ReadOnlyDirectoryIsAClearError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root can write into read-only directories";
  ScratchDir dir;
  std::filesystem::create_directory(dir / "ro");
  std::filesystem::permissions(
      dir / "ro", std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  try {
    AtomicHdf5File file((dir / "ro" / "x.h5").string());
    FAIL() << "no error for a read-only directory";
  } catch (const Hdf5Error& e) {
    EXPECT_NE(std::string(e.what()).find("not writable"), std::string::npos) << e.what();
  }
  std::filesystem::permissions(dir / "ro", std::filesystem::perms::owner_all);
}

TEST(AtomicHdf5File, EveryDatasetCarriesItsUnitsAndDescription) {
  ScratchDir dir;
  const auto path = dir / "described.h5";
  {
    AtomicHdf5File file(path.string());
    file.root().write_dataset(
        "theta0", std::span<const double>(std::vector<double>{1.0}), "rad", "tip angle");
    file.root().write_scalar("E", 2.0e11, "Pa", "Young's modulus");
    file.root().write_dataset("names", std::vector<std::string>{"a"}, "text", "names of the rows");
    write_provenance(file.root(), {});
    file.commit();
  }
  hid_t file = test::open_read_only(path);
  ASSERT_GE(file, 0);
  EXPECT_EQ(test::read_string_attribute(file, "theta0", "units"), "rad");
  EXPECT_EQ(test::read_string_attribute(file, "theta0", "description"), "tip angle");
  EXPECT_EQ(test::read_string_attribute(file, "E", "units"), "Pa");
  EXPECT_EQ(test::read_doubles(file, "E"), std::vector<double>{2.0e11}) << "a scalar dataset";
  EXPECT_EQ(test::read_string_attribute(file, "names", "units"), "text");
  H5Fclose(file);
}

TEST(AtomicHdf5File, ADatasetWithoutUnitsOrOneLineDescriptionIsRefused) {
  ScratchDir dir;
  {
    AtomicHdf5File file((dir / "x.h5").string());
    const std::vector<double> one{1.0};
    EXPECT_THROW(file.root().write_dataset("a", std::span<const double>(one), "", "a value"),
                 Hdf5Error);
    EXPECT_THROW(file.root().write_dataset("b", std::span<const double>(one), "1", ""), Hdf5Error);
    EXPECT_THROW(file.root().write_dataset("c", std::span<const double>(one), "1", "two\nlines"),
                 Hdf5Error);
    EXPECT_THROW(file.root().write_scalar("d", 1.0, "", "a value"), Hdf5Error);
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(AtomicHdf5File, CommitRefusesAFileWithoutProvenanceAndLeavesTheTargetAlone) {
  ScratchDir dir;
  const auto path = dir / "old.h5";
  std::ofstream(path) << "previous contents";
  AtomicHdf5File file(path.string());
  file.root().set_attribute("x", 1.0);
  try {
    file.commit();
    FAIL() << "a file without provenance was committed";
  } catch (const Hdf5Error& e) {
    EXPECT_NE(std::string(e.what()).find("write_provenance"), std::string::npos) << e.what();
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"old.h5"}) << "temporary left behind";
  EXPECT_EQ(test::read_text(path), "previous contents");
}

// A dataset of any rank written in row-major ranges (Hdf5Dataset::write_range, as the sweeps and
// the map write their blocks, in any order: the ranks of an MPI run finish blocks out of order)
// reads back as the whole: value i at row-major position i. The ranges are a seeded random
// partition, so they start and end inside rows, planes and blocks of every axis.
TEST(AtomicHdf5File, RowMajorRangesOfAnyRankFillTheDatasetInOrder) {
  ScratchDir dir;
  const std::vector<std::vector<hsize_t>> shapes = {
      {17}, {4, 7}, {3, 4, 5}, {2, 3, 4, 5}, {3, 1, 6, 2}, {1, 1, 1, 9}};
  std::mt19937 random(20261124);
  {
    AtomicHdf5File file((dir / "ranges.h5").string());
    for (std::size_t s = 0; s < shapes.size(); ++s) {
      hsize_t n = 1;
      for (hsize_t d : shapes[s]) n *= d;
      Hdf5Dataset values = file.root().create_dataset(
          "d" + std::to_string(s), Hdf5Type::kFloat64, shapes[s], "1", "row-major index");
      Hdf5Dataset codes = file.root().create_dataset(
          "i" + std::to_string(s), Hdf5Type::kInt32, shapes[s], "1", "row-major index");
      // Cut [0, n) at random points; write the pieces in a random order.
      std::vector<std::pair<hsize_t, hsize_t>> pieces;
      for (hsize_t at = 0; at < n;) {
        const hsize_t length = std::min<hsize_t>(n - at, 1 + random() % 11);
        pieces.emplace_back(at, length);
        at += length;
      }
      std::shuffle(pieces.begin(), pieces.end(), random);
      for (const auto& [begin, length] : pieces) {
        std::vector<double> v(length);
        std::vector<int> c(length);
        for (hsize_t k = 0; k < length; ++k) {
          v[k] = static_cast<double>(begin + k);
          c[k] = static_cast<int>(begin + k);
        }
        values.write_range(begin, std::span<const double>(v));
        codes.write_range(begin, std::span<const int>(c));
      }
      EXPECT_THROW(values.write_range(n - 1, std::span<const double>(std::vector<double>(2))),
                   Hdf5Error);
    }
    write_provenance(file.root(), {});
    file.commit();
  }
  const hid_t f = test::open_read_only(dir / "ranges.h5");
  ASSERT_GE(f, 0);
  for (std::size_t s = 0; s < shapes.size(); ++s) {
    const std::vector<double> v = test::read_doubles(f, ("d" + std::to_string(s)).c_str());
    const std::vector<int> c = test::read_ints(f, ("i" + std::to_string(s)).c_str());
    ASSERT_EQ(v.size(), c.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      ASSERT_EQ(v[i], static_cast<double>(i)) << "shape " << s << " at " << i;
      ASSERT_EQ(c[i], static_cast<int>(i)) << "shape " << s << " at " << i;
    }
  }
  H5Fclose(f);
}

TEST(Provenance, RootAttributesSayWhatMadeTheFile) {
  ScratchDir dir;
  const auto path = dir / "p.h5";
  const char* argv[] = {"flexure", "sweep", "beam", "--out", "my file.h5"};
  record_command_line(5, argv);
  {
    AtomicHdf5File file(path.string());
    write_provenance(file.root(),
                     {{"status", 0, "converged"}, {"status", 1, "no solution"}, {"v", -1, "n/a"}});
    file.commit();
  }
  hid_t file = test::open_read_only(path);
  ASSERT_GE(file, 0);
  EXPECT_EQ(test::read_string_attribute(file, "/", "tool"), "flexure");
  EXPECT_EQ(test::read_string_attribute(file, "/", "tool_version"), kVersion);
  EXPECT_EQ(test::read_string_attribute(file, "/", "git_commit"), kGitCommit);
  EXPECT_EQ(test::read_string_attribute(file, "/", "command_line"),
            "flexure sweep beam --out 'my file.h5'");
  EXPECT_EQ(test::read_string_attribute(file, "/", "status_meanings"),
            "status 0: converged\nstatus 1: no solution\nv -1: n/a");
  const std::string time = test::read_string_attribute(file, "/", "creation_time");
  std::tm tm{};
  EXPECT_NE(strptime(time.c_str(), "%Y-%m-%dT%H:%M:%SZ", &tm), nullptr) << time;
  EXPECT_EQ(time.size(), 20u) << time;
  H5Fclose(file);
}

TEST(Provenance, ShellQuoteLeavesPlainWordsAndQuotesTheRest) {
  EXPECT_EQ(shell_quote("--alpha2"), "--alpha2");
  EXPECT_EQ(shell_quote("0:10:2000"), "0:10:2000");
  EXPECT_EQ(shell_quote("/tmp/a_b-c.h5"), "/tmp/a_b-c.h5");
  EXPECT_EQ(shell_quote(""), "''");
  EXPECT_EQ(shell_quote("a b"), "'a b'");
  EXPECT_EQ(shell_quote("1A-lpp'"), R"('1A-lpp'\''')");
  EXPECT_EQ(shell_quote("$HOME"), "'$HOME'");
}

}  // namespace
}  // namespace flexure::io
