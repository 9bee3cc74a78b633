#pragma once
// How much memory a run may plan to use: the default from the machine's physical memory, and the
// text form of the --max-memory option.

#include <string>
#include <string_view>

namespace rheomag {

/// Physical memory of the machine [bytes] (sysconf); 0 when unknown.
double physical_memory_bytes();

/// Default memory limit of a run [bytes]: 3/4 of the physical memory (the rest for the system
/// and other programs); 4 GiB when the physical memory is unknown.
double default_memory_limit();

/// A memory size from text: a positive number of bytes with an optional suffix K, M, G or T
/// (powers of 1024; "8G", "512M", "2.5e9"). InputError naming `option` otherwise.
double parse_memory_size(std::string_view text, std::string_view option);

/// "7.1 GB" (three significant digits, powers of 1000) for messages.
std::string memory_size_text(double bytes);

}  // namespace rheomag
