# `cpack -G DEB` in a build folder: a Debian package of the install (CMakeLists.txt's install
# rules) under /usr, so that /usr/bin/collido finds /usr/lib/collido/plugins and
# /usr/share/collido as an install under any prefix does. The runtime libraries it needs (the
# engines the plugins link, libstdc++, ...) become Depends through dpkg-shlibdeps; the headers
# the SDK's components include (Eigen for plugin_api; CGAL, assimp and oneTBB for obbtree; the
# rest for core) are Recommends, for those who build against it.
set(CPACK_PACKAGE_NAME collidoscope)
set(CPACK_PACKAGE_VENDOR "Collidoscope")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "Compares collision-detection backends (its own OBB tree, FCL, Bullet, ODE, OpenCASCADE) on "
    "non-convex, deforming and CAD geometry, every answer checked against an exact reference. "
    "Holds the collido tool, the backend plugins, the plugin conformance kit, the bundled scenes "
    "and the SDK (headers, static libraries, CMake package Collidoscope).")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "Collidoscope developers <collidoscope@users.noreply.invalid>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "libeigen3-dev, libcgal-dev, libassimp-dev, libtbb-dev, libboost-dev, nlohmann-json3-dev, \
libpng-dev, libxxhash-dev, libopenvdb-dev, pkg-config, cmake")
set(CPACK_GENERATOR DEB)
include(CPack)
