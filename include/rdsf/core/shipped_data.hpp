#pragma once
// Where the files shipped with the workbench are: the default model and the training recipes (the source
// tree's models/: people/v1.yml and v2.yml, recipes/*.yml), for the copy of the library that is running. In order:
//   1. installed: <folder of the binary holding librdsf>/<path from LIBDIR to DATADIR/rdsf/models>, when
//      that folder exists (the shared library in LIBDIR; with a static librdsf the program in BINDIR), so
//      an installed tree may be moved to another prefix (a .deb installs under /usr);
//   2. a binary of the build tree that built the library (under its build folder or the top project's, when
//      included with add_subdirectory): the source tree's models/;
//   3. otherwise (a static librdsf inside a downstream program): DATADIR/rdsf/models of the configured
//      install prefix, when it exists.
// The paths are compiled in (src/CMakeLists.txt); nothing depends on the working folder or environment.
#include <string>

namespace rdsf {

/// The folder of the shipped models and recipes (see above); empty when none of the three exists.
std::string shipped_data_models_dir();

}  // namespace rdsf
