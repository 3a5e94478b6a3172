#pragma once
// Manufacturing tolerances of a mechanism design (docs/tolerance.md): the design's flexure
// thicknesses and widths, its lengths (the PRBM links r2, r3 and every small-length flexure's own
// length; a long segment follows its link, r/gamma) and its Young's modulus are sampled around
// their nominal values (seeded; each flexure and each length its own draw, E one draw: a batch of
// material), every sample analysed by the PRBM and (unless PRBM only) the exact model, and the
// distributions of the quantities `mechanism analyze` reports summarised; the first-order
// sensitivities come from central differences at the nominal design, and with them the
// first-order standard deviation sqrt(sum (dQ/de_k sigma_k)^2) that the sampled one approaches
// for small spreads.
//
// Under mpirun (docs/scaling.md) the analyses -- the 2 x parameters of the central differences and
// the samples, one item each -- are divided over the ranks (io/platform/work_distribution.h); the
// draws are made up front from the one seeded stream, every item is computed alone from the same
// input, and the results come back to every rank in item order, so that any number of ranks gives
// the serial study bit for bit.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "flexure/io/csv_table.h"
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

enum class SpreadDistribution { kNormal, kUniform };
const char* spread_distribution_name(SpreadDistribution d);
// "normal" or "uniform"; throws InvalidInput listing them.
SpreadDistribution parse_spread_distribution(const std::string& name);

// Relative spreads (0.03 = 3 %): the standard deviation of a normal draw, the half-width of a
// uniform one. 0 keeps a parameter at its nominal value.
struct ToleranceSpread {
  double thickness = 0.0, width = 0.0, length = 0.0, E = 0.0;
};

struct ToleranceOptions {
  ToleranceSpread spread;
  SpreadDistribution distribution = SpreadDistribution::kNormal;
  int samples = 100;
  std::uint64_t seed = 1;
  bool exact = true;  // also the exact model (else PRBM only)
  int points = 50;    // stroke points of each analysis
  // What the mean forces are the force of (mechanism.h): one half, as `mechanism analyze` reports
  // by default, or the whole symmetric mechanism (= 2 x half).
  ForceOf force_of = ForceOf::kOneHalf;
  // Throws InvalidInput naming the field: spreads finite in [0, 0.3) (a normal draw is cut at
  // 3.5 sigma, and no dimension may go to zero), samples in [2, 100000], points in [2, 10000].
  void validate() const;
};

// One quantity over the samples.
struct ToleranceStats {
  std::string name;  // the key `mechanism analyze --json` uses: "mean_force_exact", ...
  std::string unit;
  double nominal = 0.0;
  double mean = 0.0, std = 0.0, p05 = 0.0, p50 = 0.0, p95 = 0.0;
  // dQ/d(relative change) of every thickness, every width, every length, E together (the sum of
  // the single parameters' derivatives), and the first-order standard deviation.
  std::array<double, 4> sensitivity{};
  double first_order_std = 0.0;
  std::vector<double> values;  // one per sample that was analysed
};

struct ToleranceStudy {
  std::string design;
  ToleranceOptions options;
  // The sampled parameters: their names ("thickness 1", "width 1", "r2", "length 2", "E") and the
  // relative change of each in each sample (samples x parameters, row-major).
  std::vector<std::string> parameters;
  std::vector<double> draws;
  // Per parameter: dQ/d(relative change) for each quantity (quantities x parameters, row-major).
  std::vector<double> parameter_sensitivity;
  std::vector<ToleranceStats> quantities;
  int failed_samples = 0;     // samples whose design or analysis failed (left out)
  std::string first_failure;  // the first one's reason
  // For people: "N of M samples could not be analysed and are left out (first: ...)" when
  // failed_samples > 0 (kOther).
  std::vector<Warning> warnings;
  int mpi_ranks = 1;  // the ranks the analyses were divided over
};

// Throws InvalidInput for bad options or a design that cannot be analysed at its nominal values.
ToleranceStudy mechanism_tolerance(const MechanismDesign& design, const ToleranceOptions& options);

// The study as an HDF5 file (docs/hdf5-schema.md "flexure mechanism tolerance"): root attributes
// (design, distribution, samples, seed, spreads, force_of, mpi_ranks), /parameters, /draws, and per
// quantity a group with its values, sensitivities and statistics.
void write_tolerance_file(io::Hdf5Group& root, const ToleranceStudy& study);

// Writes the study (write_tolerance_file) to the HDF5 file `path`, whole or not at all
// (AtomicHdf5File). Throws Hdf5Error when the file cannot be written.
void write_tolerance_hdf5(const std::string& path, const ToleranceStudy& study);

// The samples as a CSV table (docs/cli.md "CSV output"), one row per sample: `sample` (0-based, as
// the failure messages count), the relative change of each parameter (`draws/thickness_1`, ...,
// `draws/E`, unit 1: the rows of /draws) and each quantity's value (`mean_force_prbm [N]`, ...;
// empty where the sample's analysis failed: the /<quantity>/values of the HDF5 file).
std::vector<io::CsvColumn> tolerance_csv_columns(const ToleranceStudy& study);

}  // namespace flexure::mechanism
