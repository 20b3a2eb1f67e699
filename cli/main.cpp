// facetlight: the command-line face of the photon-mapping core.
#include <iostream>

#include "commands.h"
#include "error.h"

int main(int argc, char** argv) {
    CLI::App app{"facetlight: how light moves through cut gemstones"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "facetlight 0.1.0");
    facetlight::cli::addInfoCommand(app);
    facetlight::cli::addCutCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const facetlight::Error& e) {
        std::cerr << "facetlight: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "facetlight: internal error: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
