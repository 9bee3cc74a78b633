// rheomag export: a case (TOML or .fem) written as a FEMM 4.2 .fem model.

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "case/case_file.hpp"
#include "case/femm_export.hpp"
#include "case/femm_sidecar.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_set.hpp"
#include "magnetostatics/domain.hpp"

namespace {

struct ExportCommandOptions {
  std::string case_path;
  std::vector<std::string> settings;  // --set KEY=VALUE
  std::string fem;
};

void run(const ExportCommandOptions& o) {
  const rheomag::cases::Case c = rheomag::app::load_case(o.case_path, o.settings);
  const rheomag::cases::Problem closed = rheomag::magnetostatics::close_domain(c.problem);
  const std::string sidecar = rheomag::cases::femm_sidecar_text(c, closed);
  const std::filesystem::path sidecar_path = rheomag::cases::femm_sidecar_path(o.fem);
  if (!sidecar.empty() && std::filesystem::exists(sidecar_path) &&
      !rheomag::cases::is_femm_sidecar(sidecar_path))
    throw rheomag::InputError(sidecar_path.string() +
                              " exists and is not a FEMM sidecar (no [fem] table); the gaps of " +
                              o.fem + " go there: choose another name for the .fem");
  // The model and its sidecar replace an earlier pair together.
  rheomag::OutputSet pair(std::filesystem::path(o.fem).parent_path(), "--fem " + o.fem,
                          rheomag::OutputSet::Folder::must_exist);
  const std::string model = rheomag::cases::write_femm(closed, {});
  pair.write(std::filesystem::path(o.fem).filename().string(),
             [&](const std::filesystem::path& to) { rheomag::write_file_atomically(to, model); });
  if (!sidecar.empty())
    pair.write(sidecar_path.filename().string(), [&](const std::filesystem::path& to) {
      rheomag::write_file_atomically(to, sidecar);
    });
  pair.commit();
  std::cout << "wrote " << o.fem << " (FEMM 4.2 magnetostatic model)\n";
  if (!sidecar.empty())
    std::cout << "wrote " << sidecar_path.string() << " (its fluid gaps, for rheomag)\n";
}

const bool export_registered = rheomag::app::register_command([](CLI::App& root) {
  auto o = std::make_shared<ExportCommandOptions>();
  CLI::App* cmd = root.add_subcommand(
      "export",
      "Write a case as a FEMM 4.2 .fem model that FEMM (or xfemm) opens and solves.\n"
      "Geometry (arcs as the polylines rheomag meshes), the automatic outer boundary as FEMM\n"
      "boundary segments (open = mixed condition c0 = 1/(mu0 R0)), materials with their B-H\n"
      "tables, circuits (series, turns per block), mesh sizes (FEMM sizes giving rheomag's\n"
      "mesh density, fluid gaps included). `rheomag solve OUT.fem` reads it back.\n"
      "A case with fluid gaps also gets OUT.toml beside OUT.fem (its gaps, fluid and [valve]/\n"
      "[damper] sections), so `rheomag valve OUT.fem` works as on the case.\n"
      "Exit codes: 0 success, 2 bad input.");
  cmd->add_option("CASE", o->case_path, "Case file (.toml) or FEMM model (.fem)")->required();
  cmd->add_option("--fem", o->fem, "Output .fem file")->required();
  rheomag::app::add_set_option(cmd, o->settings);
  cmd->callback([o] { run(*o); });
});

}  // namespace
