// crux: a climbing virtual human that learns and transfers (Libeau, Micaelli, Sigaud).

#include <cstdio>
#include <exception>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/parameter_binding.hpp"
#include "cli/suggestion.hpp"
#include "common/atomic_file.hpp"
#include "common/build_info.hpp"
#include "common/input_error.hpp"
#include "common/printable.hpp"

namespace {

// "crux" or "crux wall show": the command path of `command`.
std::string command_path(const CLI::App* command) {
  std::string path = command->get_name();
  for (const CLI::App* parent = command->get_parent(); parent != nullptr; parent = parent->get_parent()) {
    path = parent->get_name() + " " + path;
  }
  return path;
}

int refuse(const std::string& message) {
  std::fprintf(stderr, "crux: %s\n", message.c_str());
  return 2;
}

std::string hint(const std::string& nearest) {
  return nearest.empty() ? std::string() : fmt::format(" (did you mean '{}'?)", nearest);
}

// Flags of crux 0.1 before every parameter took its config key's name.
const std::map<std::string, std::string>& renamed_flags() {
  static const std::map<std::string, std::string> renamed{{"--solver", "--ik-solver"},
                                                          {"--alpha", "--ik-alpha"},
                                                          {"--time-step", "--ik-time-step"},
                                                          {"--timeout", "--ik-timeout"},
                                                          {"--fast-max-iterations", "--ik-fast-max-iterations"},
                                                          {"--fast-stall-decrease", "--ik-fast-stall-decrease"},
                                                          {"--fast-stall-iterations", "--ik-fast-stall-iterations"},
                                                          {"--fast-aim", "--ik-fast-aim"},
                                                          {"--grasp-radius", "--ik-grasp-radius"},
                                                          {"--root-tolerance", "--ik-root-tolerance"},
                                                          {"--wall-distance", "--ik-wall-distance"},
                                                          {"--cache-unreachable", "--ik-cache-unreachable"},
                                                          {"--learning-rate", "--learning-alpha"},
                                                          {"--gamma", "--learning-gamma"},
                                                          {"--epsilon", "--learning-epsilon"},
                                                          {"--planning-steps", "--learning-planning-steps"},
                                                          {"--planner", "--learning-planner"},
                                                          {"--priority-threshold", "--learning-priority-threshold"},
                                                          {"--max-span", "--filter-max-span"},
                                                          {"--reading", "--filter-reading"},
                                                          {"--hold-radius", "--wall-hold-radius"},
                                                          {"--finish-height", "--wall-finish-height"},
                                                          {"--wall", "--wall-file"},
                                                          {"--qgrid", "--q-grid"},
                                                          {"--columns", "--wall-columns"},
                                                          {"--rows", "--wall-rows"},
                                                          {"--tile-width", "--wall-tile-width"},
                                                          {"--tile-height", "--wall-tile-height"},
                                                          {"--sigma", "--wall-sigma"},
                                                          {"--name", "--wall-name"},
                                                          {"--grid", "--limb"},
                                                          {"--walls", "--wall-count"},
                                                          {"--seed", "--wall-seed"},
                                                          {"--svg", "--output"},
                                                          {"--path-out", "--output"},
                                                          {"--replay-run", "--run"},
                                                          {"--queries", "--compare-queries"},
                                                          {"--walk-solver", "--compare-walk-solver"}};
  return renamed;
}

// Unknown commands and options get a one-line answer with the nearest name, before
// CLI11, whose messages name neither the command nor what was meant.
int check_names(const CLI::App& app, int argc, char** argv, const CLI::App*& command) {
  command = &app;
  bool after_command = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;
    if (arg.rfind("--", 0) == 0) {
      const std::string name = arg.substr(0, arg.find('='));
      if (name == "--help" || name == "--version") return 0;
      if (command->get_option_no_throw(name) != nullptr) continue;
      std::vector<std::string> flags;
      for (const CLI::Option* option : command->get_options()) {
        if (!option->get_lnames().empty()) flags.push_back("--" + option->get_lnames().front());
      }
      const auto renamed = renamed_flags().find(name);
      const bool known_rename = renamed != renamed_flags().end() && command->get_option_no_throw(renamed->second);
      return refuse(fmt::format(
          "unknown option {} of '{}'{} (see '{} --help')", crux::printable(name), command_path(command),
          known_rename ? fmt::format(" (it is now {})", renamed->second) : hint(crux::cli::nearest_name(name, flags)),
          command_path(command)));
    }
    if (arg.rfind('-', 0) == 0) continue;  // a short option or a negative number
    if (after_command) continue;           // a value
    std::vector<std::string> names;
    for (const CLI::App* sub : command->get_subcommands([](const CLI::App*) { return true; })) {
      names.push_back(sub->get_name());
    }
    if (names.empty()) {
      after_command = true;
      continue;
    }
    const auto sub = std::find(names.begin(), names.end(), arg);
    if (sub == names.end()) {
      const std::string parent = command == &app ? std::string() : command_path(command).substr(5) + " ";
      const std::string nearest = crux::cli::nearest_name(arg, names);
      return refuse(fmt::format("unknown command '{}{}'{} (see '{} --help')", parent, crux::printable(arg),
                                hint(nearest.empty() ? nearest : parent + nearest), command_path(command)));
    }
    command = command->get_subcommand(arg);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "crux: a 32-DOF virtual human that learns to climb walls of holds by reinforcement learning and\n"
      "transfers what it learnt to new walls (after Libeau, Micaelli & Sigaud). Run 'crux <command> --help'.\n"
      "Every parameter is a flag and a config key: --section-name is the key section.name of --config FILE\n"
      "(--name for the section experiment)."};
  app.name("crux");
  app.require_subcommand(1);
  app.set_version_flag("--version", fmt::format("crux {}{}", crux::crux_version(),
                                                crux::git_commit().empty() ? "" : " (" + crux::git_commit() + ")"));
  crux::cli::add_model_command(app);
  crux::cli::add_ik_commands(app);
  crux::cli::add_demo_command(app);
  crux::cli::add_wall_command(app);
  crux::cli::add_export_command(app);
  crux::cli::add_filter_stats_command(app);
  crux::cli::add_stances_command(app);
  crux::cli::add_learning_commands(app);
  crux::cli::add_sweep_command(app);
  crux::cli::add_view_command(app);
  crux::cli::add_report_commands(app);
  const CLI::App* command = &app;
  if (const int refused = check_names(app, argc, argv, command); refused != 0) return refused;
  crux::remove_temporaries_on_signals();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const crux::cli::DryRunDone&) {
    return 0;
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // the command has already reported why
  } catch (const CLI::ExtrasError& e) {
    const std::string wall_hint =
        command->get_option_no_throw("--wall-file") != nullptr ? "; a wall file is given with --wall-file FILE" : "";
    return refuse(fmt::format("'{}' does not take {}{} (see '{} --help')", command_path(command),
                              crux::printable(e.what() + std::string_view(e.what()).find(':') + 2), wall_hint,
                              command_path(command)));
  } catch (const CLI::ConversionError& e) {
    // CLI11 says "Could not convert: --flag = value"; name the flag first, as elsewhere.
    const std::string_view what = e.what();
    const std::size_t colon = what.find(": "), equals = what.find(" = ");
    if (colon != std::string_view::npos && equals != std::string_view::npos && equals > colon) {
      return refuse(fmt::format("{}: '{}' is out of range or not of the option's type (see '{} --help')",
                                what.substr(colon + 2, equals - colon - 2), crux::printable(what.substr(equals + 3)),
                                command_path(command)));
    }
    return refuse(fmt::format("{} (see '{} --help')", crux::printable(what), command_path(command)));
  } catch (const CLI::ParseError& e) {
    // CLI11 quotes the values it refuses as given.
    return refuse(fmt::format("{} (see '{} --help')", crux::printable(e.what()), command_path(command)));
  } catch (const crux::InputError& e) {
    return refuse(e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crux: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
