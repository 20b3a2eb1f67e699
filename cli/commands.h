#pragma once
// Each subcommand of the facetlight tool lives in its own cli/<name>_command.cpp and registers itself here.
#include <CLI/CLI.hpp>

namespace facetlight::cli {

void addInfoCommand(CLI::App& app);
void addCutCommand(CLI::App& app);
void addTraceCommand(CLI::App& app);
void addStudyCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addSweepCommand(CLI::App& app);
void addPolariscopeCommand(CLI::App& app);
void addDoublingCommand(CLI::App& app);

}  // namespace facetlight::cli
