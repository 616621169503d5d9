# ROS 1 from Debian's packages, without a catkin workspace (the ROS node rdsf_people in ros/). Sets
# rdsf_ros_found ON when everything below is there, and then defines:
#   rdsf_ros1            an INTERFACE target: roscpp, message_filters, sensor_msgs, cv_bridge, image_transport,
#                        visualization_msgs, diagnostic_msgs, std_msgs, geometry_msgs (headers as system headers)
#   RDSF_ROS_PYTHON      a Python 3 that imports genmsg and gencpp (Debian's /usr/bin/python3 first: a pyenv or
#                        virtualenv python3 earlier on PATH does not see Debian's modules)
#   RDSF_GENCPP_SCRIPT   gencpp's generator (gen_cpp.py) and RDSF_GENCPP_TEMPLATE_DIR its msg.h.template
#   RDSF_ROS_MSG_INCLUDE_FLAGS  "-I pkg:dir" for the message definitions ours use (std_msgs, geometry_msgs,
#                        sensor_msgs: Debian's ros-*-msgs packages)
# Debian packages (scripts/setup.sh): libroscpp-dev libmessage-filters-dev libsensor-msgs-dev libcv-bridge-dev libimage-transport-dev
# libvisualization-msgs-dev libdiagnostic-msgs-dev python3-genmsg python3-gencpp ros-std-msgs ros-geometry-msgs
# ros-sensor-msgs.
set(rdsf_ros_found OFF)
set(rdsf_ros_missing "")
find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(RDSF_ROS QUIET IMPORTED_TARGET
    roscpp message_filters sensor_msgs cv_bridge visualization_msgs diagnostic_msgs std_msgs geometry_msgs)
endif()
if(NOT RDSF_ROS_FOUND)
  list(APPEND rdsf_ros_missing "roscpp/message_filters/sensor_msgs/cv_bridge/visualization_msgs/diagnostic_msgs (pkg-config)")
endif()
# image_transport's .pc file and CMake config require pluginlib, and Debian 12's pluginlib-dev is the ROS 2
# one (ament): found here by its header and library instead.
find_path(RDSF_IMAGE_TRANSPORT_INCLUDE_DIR image_transport/image_transport.h)
find_library(RDSF_IMAGE_TRANSPORT_LIBRARY image_transport)
if(NOT RDSF_IMAGE_TRANSPORT_INCLUDE_DIR OR NOT RDSF_IMAGE_TRANSPORT_LIBRARY)
  list(APPEND rdsf_ros_missing "image_transport")
endif()

# The message generator.
if(NOT RDSF_ROS_PYTHON)
  foreach(candidate /usr/bin/python3 python3)
    find_program(rdsf_python_candidate ${candidate} NO_CACHE)
    if(rdsf_python_candidate)
      execute_process(COMMAND ${rdsf_python_candidate} -c "import genmsg, gencpp"
                      RESULT_VARIABLE rdsf_python_result OUTPUT_QUIET ERROR_QUIET)
      if(rdsf_python_result EQUAL 0)
        set(RDSF_ROS_PYTHON ${rdsf_python_candidate} CACHE FILEPATH "Python 3 that imports genmsg and gencpp")
        break()
      endif()
    endif()
    unset(rdsf_python_candidate)
  endforeach()
endif()
if(NOT RDSF_ROS_PYTHON)
  list(APPEND rdsf_ros_missing "a python3 with genmsg and gencpp")
endif()
find_file(RDSF_GENCPP_SCRIPT gen_cpp.py PATH_SUFFIXES lib/gencpp)
find_path(RDSF_GENCPP_TEMPLATE_DIR msg.h.template PATH_SUFFIXES share/gencpp gencpp)
if(NOT RDSF_GENCPP_SCRIPT OR NOT RDSF_GENCPP_TEMPLATE_DIR)
  list(APPEND rdsf_ros_missing "gencpp (gen_cpp.py, msg.h.template)")
endif()
set(RDSF_ROS_MSG_INCLUDE_FLAGS "")
foreach(package_and_file std_msgs/Header geometry_msgs/Point sensor_msgs/RegionOfInterest)
  string(REPLACE "/" ";" parts ${package_and_file})
  list(GET parts 0 package)
  list(GET parts 1 message)
  find_path(RDSF_${package}_MSG_DIR ${message}.msg PATH_SUFFIXES share/${package}/msg ${package}/msg)
  if(RDSF_${package}_MSG_DIR)
    list(APPEND RDSF_ROS_MSG_INCLUDE_FLAGS -I ${package}:${RDSF_${package}_MSG_DIR})
  else()
    list(APPEND rdsf_ros_missing "${package}'s .msg files")
  endif()
endforeach()

if(rdsf_ros_missing STREQUAL "")
  set(rdsf_ros_found ON)
  add_library(rdsf_ros1 INTERFACE)
  target_include_directories(rdsf_ros1 SYSTEM INTERFACE ${RDSF_IMAGE_TRANSPORT_INCLUDE_DIR})
  target_link_libraries(rdsf_ros1 INTERFACE PkgConfig::RDSF_ROS ${RDSF_IMAGE_TRANSPORT_LIBRARY})
else()
  string(REPLACE ";" ", " rdsf_ros_missing_text "${rdsf_ros_missing}")
  message(STATUS "ROS 1 not found (the node rdsf_people is not built): missing ${rdsf_ros_missing_text}")
endif()
