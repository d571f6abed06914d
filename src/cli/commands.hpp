#pragma once
// Each subcommand registers itself on the application; its callback throws InputError
// for bad input, which main turns into one line on stderr and exit code 2.

#include <CLI/CLI.hpp>

namespace crux::cli {

void add_model_command(CLI::App& app);
void add_ik_commands(CLI::App& app);
void add_demo_command(CLI::App& app);
void add_filter_stats_command(CLI::App& app);
void add_stances_command(CLI::App& app);
void add_wall_command(CLI::App& app);
void add_export_command(CLI::App& app);
void add_learning_commands(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_view_command(CLI::App& app);
void add_report_commands(CLI::App& app);

}  // namespace crux::cli
