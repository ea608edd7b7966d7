# The Debian package (CPack's DEB generator): scripts/package.sh builds it, and
# scripts/check-package.sh runs lintian on it. docs/packaging.md describes both.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME rasterlab)
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_VENDOR "The RasterLab developers")
set(CPACK_PACKAGE_CONTACT "${RASTERLAB_PACKAGE_MAINTAINER}")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
# Directories 0755 whatever the umask of the machine that builds the package.
set(CPACK_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
    OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)          # rasterlab_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)           # Depends from the libraries linked (dpkg-dev)
# Qt's platform plugins are loaded at run time, not linked: the window needs one (xcb on a
# desktop, offscreen for scripts), and Qt's own translations for its dialogs in Portuguese.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-translations-l10n, fonts-dejavu-core")
# The synopsis, then the long description: CPack indents its lines and turns the empty line
# into the paragraph break (" ."). No semicolons: CMake would split the text into a list.
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "software rasterization pipeline with observable stages, for teaching")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
"RasterLab teaches the classic rasterization pipeline by letting a class
watch it work. A scene (a camera, a light and a triangle mesh in the
UFPE/UFRPE course file formats, or a command file of the HW2 rasterizer
language) goes through seven observable stages: camera basis, view
transform, normals, projection with near-plane clipping, scan conversion,
depth test and shading.

Every stage keeps its output and has a view: step a frame by triangle,
scanline or pixel, pick a pixel to see every fragment and each term of its
Phong sum. The window (rasterlab) is in English and Brazilian Portuguese,
and rasterlab-cli renders, compares and measures the same scenes without
one.")

include(CPack)
