#include "cli/Cli.hpp"

#include "cli/BadInput.hpp"
#include "cli/InspectCommand.hpp"
#include "cli/MieCommand.hpp"
#include "cli/QueryCommand.hpp"
#include "cli/Ranks.hpp"
#include "cli/RayCsv.hpp"
#include "cli/SnapshotCommand.hpp"
#include "cli/TraceCommand.hpp"
#include "results/Version.hpp"
#include "scene/SceneLoader.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <exception>
#include <new>
#include <optional>
#include <ostream>
#include <string>
#include <thread>

namespace dropscope {

namespace {

// Every process an MPI launcher started parses the same arguments before MPI starts: only the first says
// what is wrong. The others wait before their exit 2, on which mpirun would end the job, so that the first
// has said it; its own exit 2 ends them sooner (docs/scaling.md).
int reportUsageError(const std::string& message, std::ostream& err) {
    if (launcherRank() == 0) {
        err << "dropscope: " << message << " (see dropscope --help)\n";
    } else {
        std::this_thread::sleep_for(std::chrono::seconds(10));
    }
    return kExitBadInput;
}

// The top level takes only flags, so its first other argument must name a command. CLI11 would call
// it an unexpected extra argument; say what it is instead.
std::optional<std::string> unknownCommand(const CLI::App& app, int argc, const char* const* argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument.starts_with("-")) continue;
        std::string known;
        for (const CLI::App* command : app.get_subcommands({})) {
            if (command->get_name() == argument) return std::nullopt;
            known += (known.empty() ? "" : ", ") + command->get_name();
        }
        return "unknown command \"" + argument + "\" (known: " + known + ")";
    }
    return std::nullopt;
}

}  // namespace

int runCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
    try {
        CLI::App app{"dropscope: light through droplets", "dropscope"};
        app.require_subcommand(0, 1);
        app.set_version_flag("--version", "dropscope " + std::string(dropscopeVersion()),
                             "Print dropscope's version and exit");
        app.footer(
            "Exit status: 0 success, 2 bad input (arguments, scene file, output path), 3 no display for the app\n"
            "(dropscope [SCENE.json] opens it), 1 internal error,\n"
            "4 trace lost more photons than --max-lost allows (results written),\n"
            "130 trace stopped by Ctrl-C (partial results written).");
        InspectOptions inspectOptions;
        const CLI::App* inspect = addInspectCommand(app, inspectOptions);
        QueryOptions queryOptions;
        const CLI::App* query = addQueryCommand(app, queryOptions);
        TraceOptions traceOptions;
        const CLI::App* trace = addTraceCommand(app, traceOptions);
        SnapshotCommandOptions snapshotOptions;
        const CLI::App* snapshot = addSnapshotCommand(app, snapshotOptions);
        MieOptions mieOptions;
        const CLI::App* mie = addMieCommand(app, mieOptions);
        if (const auto message = unknownCommand(app, argc, argv)) return reportUsageError(*message, err);
        try {
            app.parse(argc, argv);
        } catch (const CLI::CallForHelp&) {
            out << app.help();
            return kExitSuccess;
        } catch (const CLI::CallForVersion& version) {
            out << version.what() << '\n';
            return kExitSuccess;
        } catch (const CLI::ParseError& error) {
            return reportUsageError(error.what(), err);
        }
        if (inspect->parsed()) return runInspect(inspectOptions, out, err);
        if (query->parsed()) return runQuery(queryOptions, out, err);
        if (trace->parsed()) return runTraceCommand(traceOptions, out, err);
        if (snapshot->parsed()) return runSnapshotCommand(snapshotOptions, out, err);
        if (mie->parsed()) return runMieCommand(mieOptions, out, err);
        // No subcommand (main.cpp opens the app when there are no arguments at all).
        out << app.help();
        err << "dropscope: no command given (see the commands above)\n";
        return kExitBadInput;
    } catch (const std::exception&) {
        return reportFailure(std::current_exception(), err);
    }
}

int reportFailure(const std::exception_ptr& failure, std::ostream& err) {
    try {
        std::rethrow_exception(failure);
    } catch (const SceneError& error) {  // bad input found by any command: its one line
        err << error.what() << '\n';
        return kExitBadInput;
    } catch (const RayCsvError& error) {
        err << error.what() << '\n';
        return kExitBadInput;
    } catch (const BadInputError& error) {
        err << error.what() << '\n';
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        // Past the estimates every run makes up front (docs/limits.md): the machine, or ulimit, had less
        // memory than they assumed. No output was written: the writers allocate before they rename.
        err << "dropscope: out of memory: this run needs more than the machine allows (docs/limits.md, "
               "\"Memory\"); nothing was written\n";
        return kExitBadInput;
    } catch (const std::exception& error) {
        err << "dropscope: internal error: " << error.what() << '\n';
        return kExitInternalError;
    }
}

}  // namespace dropscope
