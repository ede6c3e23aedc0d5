// The option sets the doors offer, by the name they go by ("fill", ...): their schemas as JSON
// (option_schema.h) for the Python module and `holefill options`, so that a door asks for a set by
// name and never keeps a list of its own.
#pragma once

#include <string>
#include <vector>

namespace holefill {

std::vector<std::string> optionSetNames();
std::string optionSetJson(const std::string& set);  // Error for an unknown set, listing the known ones

}  // namespace holefill
