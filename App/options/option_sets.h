// The option sets the doors offer, by the name they go by ("fill", ...): their fields and defaults
// (option_schema.h) for the Python module, `holefill options` and the CLI's valueless flags, so
// that a door asks for a set by name and never keeps a list of its own.
#pragma once

#include <string>
#include <vector>

#include "options/option_schema.h"

namespace holefill {

std::vector<std::string> optionSetNames();
OptionList optionSet(const std::string& set);       // Error for an unknown set, listing the known ones
std::string optionSetJson(const std::string& set);  // optionSet(set).toJson()

}  // namespace holefill
