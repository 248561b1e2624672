#pragma once
// Where `reproduce` and `bench` find the paper's worlds when --worlds is not given: the
// working folder's worlds/paper (a clone), else the copy `make install` put in
// PREFIX/share/swarmagg/worlds/paper, so that an installed swarmagg runs from any folder.
#include <string>

namespace swarmagg::cli {

// The folder to read, or InputError naming every place looked in when neither exists.
std::string paper_worlds_folder(const std::string& given);

// What --worlds defaults to, for its help.
std::string paper_worlds_default_help();

}  // namespace swarmagg::cli
