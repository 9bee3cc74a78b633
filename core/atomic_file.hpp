#pragma once
// The one way rheomag writes an output file: a temporary file beside the target, checked
// writes, fsync, rename into place; the temporary removed on any failure and when the process
// is interrupted (SIGINT/SIGTERM, core/interrupt.hpp).

#include <filesystem>
#include <functional>
#include <string_view>

namespace rheomag {

/// Writes `content` to `path` atomically. InputError naming the path (and the system's reason)
/// when it cannot, or when `path` exists and is not a regular file (a device node, a directory);
/// the old file, if any, is then untouched. Text holding a non-finite number ("nan", "-inf") is
/// refused with NonFiniteOutputError (core/finite_output.hpp) before anything is written.
void write_file_atomically(const std::filesystem::path& path, std::string_view content);

/// Lets `produce` write a file at a temporary path beside `path` (for writers that take a file
/// name, such as VTK's or gnuplot's), then fsyncs it and renames it into place. `produce`
/// returns false (or throws) when it failed; the temporary is then removed and InputError
/// thrown (or the exception passed on). An empty file counts as a failure.
void write_file_atomically_with(const std::filesystem::path& path,
                                const std::function<bool(const std::filesystem::path&)>& produce);

/// Throws InputError unless `path` can be replaced by a regular file: it is absent or a regular
/// file, and it is not empty text. `what` names the option or output in the message.
void check_output_path(const std::filesystem::path& path, std::string_view what);

}  // namespace rheomag
