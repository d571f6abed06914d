// crux: a climbing virtual human that learns and transfers (Libeau, Micaelli, Sigaud).

#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "common/input_error.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "crux: a 32-DOF virtual human that learns to climb walls of holds by reinforcement learning and\n"
      "transfers what it learnt to new walls (after Libeau, Micaelli & Sigaud). Run 'crux <command> --help'."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "crux 0.1.0");
  crux::cli::add_model_command(app);
  crux::cli::add_ik_commands(app);
  crux::cli::add_demo_command(app);
  crux::cli::add_wall_command(app);
  crux::cli::add_filter_stats_command(app);
  crux::cli::add_learning_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // the command has already reported why
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "crux: %s (see 'crux --help')\n", e.what());
    return 2;
  } catch (const crux::InputError& e) {
    std::fprintf(stderr, "crux: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crux: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
