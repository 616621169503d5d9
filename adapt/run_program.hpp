#pragma once
// rdsf-adapt's steps run the workbench's own programs (rdsf-mine, rdsf-label, rdsf-train, rdsf-detect), so
// every step is also one command a person can run alone; this starts one and waits for it.
#include <string>
#include <vector>

namespace rdsf {

/// The path of a sibling program ("rdsf-label"): beside this one (installed) or in its folder of the build
/// tree (../labeler/rdsf-label). Throws Error when neither exists.
std::string sibling_program(const std::string& name);

/// Runs `program` with `args`; its stderr (and stdout) go to `log` (appended), after a line "$ PROGRAM ARGS"
/// (the command, quoted for a shell), unless `log` is empty (then they stay the terminal's). Returns the exit
/// code; throws Error when it cannot be started or was killed.
int run_program(const std::string& program, const std::vector<std::string>& args, const std::string& log);

/// The lines of `log` that start with `prefix` ("rdsf-label: "), the last `count` of them.
std::vector<std::string> log_lines(const std::string& log, const std::string& prefix, std::size_t count = 100);

}  // namespace rdsf
