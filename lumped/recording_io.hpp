#pragma once
// Reading and writing recordings in the fixed format of shared/docs/recording-format.md.

#include <string>
#include <string_view>
#include <vector>

#include "lumped/recording.hpp"

namespace rheomag::lumped {

/// The column names the format defines (t first); any other CSV column is ignored with a warning.
const std::vector<std::string>& known_columns();

/// The SI unit of the known column `column` as the recording format writes it ("A", "m/s", ...).
std::string column_si_unit(const std::string& column);

/// Path of the sidecar of a CSV file: same folder and stem, extension .toml.
std::string sidecar_path_for(const std::string& csv_path);

/// Reads the TOML sidecar at `toml_path`; throws InputError naming the file and key on bad input.
RecordingMeta read_sidecar(const std::string& toml_path);

/// Parses sidecar text (`toml_path` names it in messages). Every physical value has a declared
/// domain (piston_area > 0, chamber_volume > 0, rod_area >= 0 and below piston_area,
/// viscous_resistance > 0, yield_pressure >= 0, resistance > 0, inductance >= 0); a value
/// outside it is an InputError "file:line: table.key: expected ..., got ...".
RecordingMeta parse_sidecar(std::string_view text, const std::string& toml_path);

/// Parses CSV samples (`csv_path` names the file in messages): a UTF-8 byte-order mark is
/// skipped; a header without commas is refused naming the separator it seems to use.
Recording parse_csv_samples(std::string_view text, const std::string& csv_path);

/// Reads the CSV samples at `csv_path` (no sidecar); unknown columns warned about on stderr.
Recording read_csv_samples(const std::string& csv_path);

/// Reads a recording: the CSV at `csv_path` and its sidecar (missing sidecar is an InputError);
/// checks that the sidecar's drive and output columns exist in the CSV.
Recording read_recording(const std::string& csv_path);

/// Writes `rec` as `csv_path` plus its sidecar (same stem, .toml), each atomically (temp+rename).
/// Columns are written in the order of known_columns(); `rec.meta` becomes the sidecar.
void write_recording(const Recording& rec, const std::string& csv_path);

}  // namespace rheomag::lumped
