#include "figures/solve_pictures.hpp"

#include <cctype>
#include <cstdio>

#include "core/error.hpp"
#include "core/output_set.hpp"
#include "figures/gap_profile.hpp"
#include "figures/inductance.hpp"

namespace rheomag::figures {

namespace {

/// The field map's title: the case and its circuits' currents.
std::string field_map_title(const SolvedCase& solved) {
  std::string title = solved.name + ": |B| and flux lines";
  for (const magnetostatics::CircuitResult& c : solved.results.circuits) {
    char text[128];
    std::snprintf(text, sizeof text, ", %s at %g A", c.name.c_str(), c.current);
    title += text;
  }
  return title;
}

/// Stages `figure` as stem.svg and stem.png of `set`, appending their final paths to `written`.
void write_both(const plot::Figure& figure, const OutputSet& set, const std::string& stem,
                std::vector<std::filesystem::path>& written) {
  for (const char* ext : {".svg", ".png"}) {
    const std::filesystem::path path = set.folder() / (stem + ext);
    set.write(stem + ext,
              [&](const std::filesystem::path& to) { figure.write(to, path.string()); });
    written.push_back(path);
  }
}

/// True for a picture of an earlier picture set (a gap the design no longer has, a sweep's
/// lambda_L): replaced or removed with the new set.
bool is_set_picture(const std::string& name) {
  const bool picture = plot::is_picture_path(name);
  return picture && (name.rfind("gap_", 0) == 0 || name.rfind("lambda_L.", 0) == 0 ||
                     name.rfind("field_map.", 0) == 0);
}

}  // namespace

std::string file_name_part(const std::string& name) {
  std::string part = name;
  for (char& ch : part) {
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '_') ch = '_';
  }
  return part;
}

std::vector<std::filesystem::path> write_solve_pictures(const std::filesystem::path& dir,
                                                        const SolvedCase& solved,
                                                        const FieldMapOptions& options) {
  OutputSet set(dir, "--out");
  std::vector<std::filesystem::path> written;
  FieldMapOptions map_options = options;
  if (map_options.title.empty()) map_options.title = field_map_title(solved);
  write_both(draw_field_map(solved.solver, solved.solution, solved.results, map_options).figure,
             set, "field_map", written);
  for (const magnetostatics::GapResult& gap : solved.results.gaps) {
    if (gap.profile.s.empty()) continue;
    write_both(gap_profile_figure(gap, 900, 560), set, "gap_" + file_name_part(gap.name), written);
  }
  if (!solved.sweep.empty() && !solved.results.circuits.empty()) {
    write_both(inductance_figure(solved.sweep, solved.results.circuits.front().name, 900, 800), set,
               "lambda_L", written);
  }
  set.commit(is_set_picture);
  return written;
}

void write_field_map(const std::filesystem::path& path, const std::string& what,
                     const SolvedCase& solved, const FieldMapOptions& options) {
  if (!plot::is_picture_path(path))
    throw InputError(what + ": expected a file name ending in .png or .svg, got '" + path.string() +
                     "'");
  FieldMapOptions map_options = options;
  if (map_options.title.empty()) map_options.title = field_map_title(solved);
  draw_field_map(solved.solver, solved.solution, solved.results, map_options)
      .figure.write(path, what);
}

}  // namespace rheomag::figures
