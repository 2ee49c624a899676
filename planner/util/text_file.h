#pragma once
// Every input file is read through one door, so that a missing file, a folder given where a
// file was expected or an unreadable file all fail the same way: an InputError naming the path.
// (A folder opened as a std::ifstream "opens" on Linux and then throws from inside a parser that
// does not expect it — the fuzzer's find.)
#include <string>

namespace stanceplan {

// The whole file as bytes. Throws InputError "<path>: no such file", "<path>: not a regular file
// (a folder?)", "<path>: cannot be read (no permission?)" or "<path>: read error".
std::string read_text_file(const std::string& path);

}  // namespace stanceplan
