#pragma once
// Option names as people type them: every front end (the command line, --config, Python keywords,
// ROS parameters) takes robot_radius and robot-radius alike and answers a typo with the name meant.
#include <string>
#include <vector>

namespace topocut {

// name with every '_' written '-': the form the front ends compare names in.
std::string dashed_option_name(std::string name);

// name with every '-' written '_': the form of Python keywords and ROS parameters.
std::string underscored_option_name(std::string name);

// The name of known closest to name (at most two edits apart, '_' and '-' alike), or "" when none is
// that close: the "did you mean ...?" of an unknown option.
std::string closest_option_name(const std::string& name, const std::vector<std::string>& known);

}  // namespace topocut
