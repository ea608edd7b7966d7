// Where the program's own files are, found from the folder of the running executable, so that
// an installed RasterLab works under any prefix (/usr, /usr/local, a staging DESTDIR) and a
// build works from its build folder, which mirrors the installed layout (app/CMakeLists.txt
// links build/share/... to the source tree):
//
//   <bindir>/rasterlab, rasterlab-cli
//   <bindir>/../share/rasterlab/translations/rasterlab_LANG.qm   (lrelease's output)
//   <bindir>/../share/rasterlab/lessons/NAME/                     (the shipped lessons)
//   <bindir>/../share/doc/rasterlab/guide.LANG.md, images/        (the user guides)
//
// The relative paths come from CMake's install directories (GNUInstallDirs).
#pragma once

#include <QString>

namespace rasterlab {

// The folder of the program's data (`<bindir>/../share/rasterlab`), or "" when it is absent.
// appDir defaults to QCoreApplication::applicationDirPath().
QString dataDir(const QString& appDir = QString());

// The folder of the installed documentation (`<bindir>/../share/doc/rasterlab`), or "".
QString docDir(const QString& appDir = QString());

// The user guide in `language` ("pt_BR", "en", or a locale name such as "pt_BR.UTF-8"),
// falling back to English; "" when no guide is found.
QString userGuide(const QString& language, const QString& appDir = QString());

// Where our translations are: the installed .qm folder when it is there, else the copies
// embedded in the window's library (":/i18n").
QString translationsDir(const QString& appDir = QString());

}  // namespace rasterlab
