#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <set>

#include "flexure/mechanisms/data/data_files.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/solver/common/csv_table.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

constexpr double kMPa = 1e6;
constexpr double kGPa = 1e9;

std::size_t edit_distance(const std::string& a, const std::string& b);

// Lower case letters and digits only: "Steel 1095-HR" -> "steel1095hr".
std::string normalised(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  return out;
}

// Lower-case words of letters and digits ("Ti-6Al-4V annealed" -> ti, 6al, 4v, annealed).
std::set<std::string> words(const std::string& s) {
  std::set<std::string> out;
  std::string w;
  for (const char c : s + " ") {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      w += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else if (!w.empty()) {
      out.insert(w);
      w.clear();
    }
  }
  return out;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::vector<MaterialGrade> parse_library() {
  const CsvTable t = CsvTable::parse(data::materials());
  std::vector<MaterialGrade> out;
  std::set<std::string> seen;
  for (std::size_t r = 0; r < t.row_count(); ++r) {
    MaterialGrade g;
    g.id = t.text(r, "id");
    if (!seen.insert(normalised(g.id)).second) throw t.cell_error(r, "id", "a repeated id");
    g.designation = t.text(r, "designation");
    g.family = t.text(r, "class");
    g.source = t.text(r, "source");
    g.E = t.number(r, "E") * kGPa;
    g.nu = t.optional_number(r, "nu");
    if (auto v = t.optional_number(r, "S_y")) g.yield_strength = *v * kMPa;
    if (auto v = t.optional_number(r, "S_ut")) g.ultimate_strength = *v * kMPa;
    if (auto v = t.optional_number(r, "S_e")) g.fatigue_strength = *v * kMPa;
    const std::string kind = t.text(r, "fatigue_kind");
    if (kind == "endurance-limit") {
      g.fatigue_kind = FatigueStrengthKind::kEnduranceLimit;
    } else if (kind == "fatigue-strength") {
      g.fatigue_kind = FatigueStrengthKind::kFatigueStrength;
      g.fatigue_cycles = t.number(r, "fatigue_cycles");
    } else if (kind != "-") {
      throw t.cell_error(r, "fatigue_kind", "not endurance-limit, fatigue-strength or -");
    }
    if (g.fatigue_strength.has_value() != g.fatigue_kind.has_value()) {
      throw t.cell_error(r, "fatigue_kind", "given without S_e, or S_e without it");
    }
    g.density = t.optional_number(r, "density");
    g.ductile = t.yes_no(r, "ductile");
    g.fatigue_source = t.text(r, "fatigue_source");
    g.notes = t.text(r, "notes");
    if (g.fatigue_source == "-") g.fatigue_source.clear();
    if (g.notes == "-") g.notes.clear();
    try {
      g.material().validate();
    } catch (const InvalidInput& e) {
      throw t.cell_error(r, "E", e.what());
    }
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace

std::optional<double> MaterialGrade::static_strength() const {
  return ductile ? yield_strength : ultimate_strength;
}

Material MaterialGrade::material() const {
  Material m;
  m.E = E;
  m.nu = nu.value_or(0.3);
  m.yield_strength = yield_strength;
  m.density = density;
  return m;
}

const std::vector<MaterialGrade>& material_library() {
  static const std::vector<MaterialGrade> library = parse_library();
  return library;
}

std::vector<std::string> closest_material_ids(const std::string& name, std::size_t count) {
  const std::string key = normalised(name);
  const std::set<std::string> name_words = words(name);
  // Score: words in common first (more is closer), then the edit distance of the normalised ids.
  struct Scored {
    std::size_t common;
    std::size_t distance;
    std::string id;
  };
  std::vector<Scored> scored;
  for (const MaterialGrade& g : material_library()) {
    std::size_t common = 0;
    const std::set<std::string> w = words(g.id + " " + g.designation + " " + g.family);
    for (const std::string& n : name_words) {
      for (const std::string& x : w) {
        // "titanium" finds "ti-..." rows through the class; "poly" finds polypropylene.
        if (x == n || (n.size() >= 3 && x.find(n) != std::string::npos) ||
            (n.size() >= 5 && edit_distance(x, n) <= 2)) {
          ++common;
          break;
        }
      }
    }
    const std::size_t d = std::min(edit_distance(key, normalised(g.id)),
                                   edit_distance(key, normalised(g.designation)));
    if (common > 0 || d <= std::max<std::size_t>(2, key.size() / 3)) {
      scored.push_back({common, d, g.id});
    }
  }
  std::stable_sort(scored.begin(), scored.end(), [](const Scored& a, const Scored& b) {
    return a.common != b.common ? a.common > b.common : a.distance < b.distance;
  });
  std::vector<std::string> out;
  for (const Scored& s : scored) {
    if (out.size() == count) break;
    out.push_back(s.id);
  }
  return out;
}

const MaterialGrade& find_material(const std::string& name) {
  const std::string key = normalised(name);
  for (const MaterialGrade& g : material_library()) {
    if (!key.empty() && (key == normalised(g.id) || key == normalised(g.designation))) return g;
  }
  const std::vector<std::string> close = closest_material_ids(name);
  throw InvalidInput(fmt::format(
      "unknown material '{}'{}; `flexure materials` lists all {} (data/materials.csv)",
      name,
      close.empty() ? std::string() : fmt::format(" (closest: {})", fmt::join(close, ", ")),
      material_library().size()));
}

}  // namespace flexure
