// cadlod: CAD VRML to OpenFlight LOD models on the command line (no MeshLab, no X server).
// Exit codes: 0 ok, 1 input error, 2 usage error (cli_errors.h).
#include "cli_errors.h"
#include "commands.h"
#include "progress_bar.h"

#include <cstdio>
#include <string>

int main(int argc, char** argv)
{
    using namespace cadlod::cli;
    CLI::App app{"cadlod: CAD VRML to OpenFlight LOD models"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("cadlod ") + CADLOD_VERSION);
    addConvertCommand(app);
    addSimplifyCommand(app);
    addReportCommand(app);
    addInfoCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "cadlod: %s\nRun 'cadlod --help' for the commands and options.\n", e.what());
        return kUsageError;
    } catch (const UsageError& e) {
        progress::finish();
        std::fprintf(stderr, "cadlod: %s\n", e.what());
        return kUsageError;
    } catch (const InputError& e) {
        progress::finish();
        std::fprintf(stderr, "cadlod: error: %s\n", e.what());
        return kInputError;
    } catch (const std::exception& e) {
        progress::finish();
        std::fprintf(stderr, "cadlod: error: %s\n", e.what());
        return kInputError;
    }
    return kOk;
}
