#pragma once
// The one way rheomag reads an input file: refused by name unless it is a regular file (a
// device, FIFO, socket or directory is never opened for reading, so /dev/zero cannot be read to
// exhaustion and a FIFO without a writer cannot block), and bounded in size.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rheomag {

/// Largest input file read [bytes]: 1 GiB, 25 times the largest recording rheomag was measured
/// with (10^7 rows of three columns take 0.4 GB of text).
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{1} << 30;

/// Throws InputError naming `path` unless it exists and is a regular file (or a symbolic link
/// to one). `what` names the kind of input in the message ("case file", "recording").
void require_regular_input_file(const std::filesystem::path& path,
                                std::string_view what = "input file");

/// The whole content of the regular file `path`: InputError naming the path when it is missing,
/// not a regular file, larger than `max_bytes` (the size and the limit named) or unreadable.
std::string read_input_file(const std::filesystem::path& path,
                            std::uintmax_t max_bytes = kMaxInputFileBytes);

}  // namespace rheomag
