#pragma once
// How much memory a run may plan to use: the default from the machine's physical memory, and the
// text form of the --max-memory option.

#include <string>
#include <string_view>

namespace rheomag {

/// Physical memory of the machine [bytes] (sysconf); 0 when unknown.
double physical_memory_bytes();

/// Memory this process may use [bytes]: the physical memory, lowered by an address-space or
/// data limit (ulimit -v / -d) and a container's cgroup limit; 0 when unknown.
double available_memory_bytes();

/// Default memory limit of a run [bytes]: 3/4 of available_memory_bytes() (the rest for the
/// system, other programs and the code itself); 4 GiB when it is unknown.
double default_memory_limit();

/// A memory size from text: a positive number of bytes with an optional suffix K, M, G or T
/// (powers of 1024; "8G", "512M", "2.5e9"). InputError naming `option` otherwise.
double parse_memory_size(std::string_view text, std::string_view option);

/// "7.1 GB" (three significant digits, powers of 1000) for messages.
std::string memory_size_text(double bytes);

}  // namespace rheomag
