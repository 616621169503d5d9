# cmake --install BUILD --prefix P: the library, its headers, the CMake package rdsf::rdsf, rdsf.pc, the
# programs, the shipped models and recipes, the docs. cpack -G DEB packs the same tree (prefix /usr).
include(CMakePackageConfigHelpers)
set(RDSF_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/rdsf)

install(TARGETS rdsf EXPORT rdsfTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(TARGET rdsf_image_codecs)  # OpenCV's image codecs, opened by librdsf at their first use: beside it
  install(TARGETS rdsf_image_codecs LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()
# Public headers: include/rdsf/<area>/*.hpp and the generated rdsf/version.hpp. The OpenNI2 frame source's
# header only when the library has it.
set(rdsf_header_excludes)
if(NOT RDSF_WITH_OPENNI)
  set(rdsf_header_excludes PATTERN "openni_source.hpp" EXCLUDE)
endif()
if(NOT RDSF_WITH_ROSBAG)
  list(APPEND rdsf_header_excludes PATTERN "bag_source.hpp" EXCLUDE)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/rdsf DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp" ${rdsf_header_excludes})
install(FILES ${PROJECT_BINARY_DIR}/include/rdsf/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/rdsf)

install(EXPORT rdsfTargets NAMESPACE rdsf:: DESTINATION ${RDSF_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rdsfConfig.cmake.in
  ${PROJECT_BINARY_DIR}/rdsfConfig.cmake INSTALL_DESTINATION ${RDSF_INSTALL_CMAKEDIR})
# 0.x: minor versions may change the interface, so only the same MAJOR.MINOR is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rdsfConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rdsfConfig.cmake ${PROJECT_BINARY_DIR}/rdsfConfigVersion.cmake
        DESTINATION ${RDSF_INSTALL_CMAKEDIR})

# pkg-config: the prefix is found from the .pc file's own folder (${pcfiledir}), so --prefix P at install
# time, a moved prefix and the .deb's /usr all work.
set(RDSF_PC_LIBS_PRIVATE "-pthread")
if(CMAKE_DL_LIBS)
  set(RDSF_PC_LIBS_PRIVATE "-pthread -l${CMAKE_DL_LIBS}")
endif()
if(RDSF_WITH_OPENNI)
  string(APPEND RDSF_PC_LIBS_PRIVATE " -lOpenNI2")
endif()
if(RDSF_WITH_ROSBAG)
  string(APPEND RDSF_PC_LIBS_PRIVATE " -lrosbag_storage -lroscpp_serialization -lrostime -lcpp_common -lconsole_bridge")
endif()
file(RELATIVE_PATH RDSF_PC_TO_PREFIX ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" RDSF_PC_TO_PREFIX "${RDSF_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/rdsf.pc.in ${PROJECT_BINARY_DIR}/rdsf.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/rdsf.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# Programs (the bench/ ones, the doc-picture helper rdsf-side-by-side, the quality report's peer rdsf-pcl-people
# and the ROS node rdsf_people, whose package would then depend on ROS, stay in the build tree). rdsf-adapt runs
# its siblings from its own folder (adapt/run_program.hpp), so every program it runs is here too.
foreach(program rdsf-detect rdsf-background rdsf-synth rdsf-mine rdsf-samples rdsf-label rdsf-review rdsf-train
                rdsf-adapt rdsf-record)
  if(TARGET ${program})
    install(TARGETS ${program} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  endif()
endforeach()

# The shipped default model and the recipes (core/shipped_data.hpp finds them here once installed).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/models/people ${PROJECT_SOURCE_DIR}/models/recipes
        DESTINATION ${CMAKE_INSTALL_DATADIR}/rdsf/models FILES_MATCHING PATTERN "*.yml")
# The docs, laid out as in the source tree so that README's links hold.
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/datasets/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR}/datasets)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples DESTINATION ${CMAKE_INSTALL_DOCDIR})

# cpack -G DEB (from the build folder): one package "rdsf" with all of the above under /usr. Its
# dependencies: the shared libraries' packages (dpkg-shlibdeps), and the -dev packages that
# find_package(rdsf) and rdsf.pc need to compile against the headers.
if(PROJECT_IS_TOP_LEVEL)
  set(CPACK_PACKAGE_NAME rdsf)
  set(CPACK_PACKAGE_VENDOR "RDSF workbench")
  set(CPACK_PACKAGE_CONTACT "RDSF workbench maintainers <rdsf@localhost>")
  set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
  set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
  set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
  set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
  set(CPACK_DEBIAN_PACKAGE_SECTION science)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "libopencv-dev (>= 4)")
  if(NOT RDSF_SHARED)  # rdsfConfig.cmake finds Eigen3 for a static librdsf
    string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", libeigen3-dev")
  endif()
  set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
  set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
  include(CPack)
endif()
