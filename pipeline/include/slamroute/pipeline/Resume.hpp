#pragma once
// `run --resume` / `experiment --resume`: which steps of an earlier, interrupted or finished run
// can be kept. Every step that succeeds leaves a stamp beside its log (Subprocess.hpp): what it
// was run from. A step is kept only when its output exists and the stamp it would write now is
// the one on disk, so a new seed, a changed config file or net, or an upstream step whose result
// came out different runs it again; an unchanged re-run of an upstream step does not. Inputs are
// known by content, so a run folder copied elsewhere with its logs/ resumes too.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "slamroute/pipeline/Subprocess.hpp"

namespace slamroute::pipeline {

/// 64-bit hash of a file's bytes (change detection, not cryptographic; ~1 GB/s). Throws
/// std::runtime_error when the file cannot be read.
std::uint64_t fileHash(const std::filesystem::path& file);

/// Hash of a folder: every regular file under it, by relative path, size and content.
std::uint64_t folderHash(const std::filesystem::path& dir);

/// What a step is run from, as text: slamroute's version, a hash of the running program (a
/// rebuilt or upgraded binary runs every step again) and its arguments, where an existing
/// file or folder given by its absolute path stands as the hash of its content, and the values
/// of --out (the step's own output) and --log-level are left out.
std::string stepStamp(const Step& s);

/// Stamps each step (stepStamp) and, with `resume`, leaves out those done before: output exists
/// and the stamp beside its log equals the new one. An output without a stamp is made again: its
/// step was stopped, or finished as an orphan of a killed run, and may come from other inputs.
/// Each kept step is logged, and so is the reason a step with an existing output runs again.
std::vector<Step> stepsToRun(std::vector<Step> steps, bool resume);

}  // namespace slamroute::pipeline
