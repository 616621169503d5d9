# Warnings for the targets of this project only (never add_compile_options or CMAKE_CXX_FLAGS, which a
# parent project including us with add_subdirectory/FetchContent would inherit or share). At the end of
# the configure step every target defined in our folders gets the flags as a PRIVATE compile option.
set(RDSF_WARNING_FLAGS -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
                       -Woverloaded-virtual)
if(RDSF_WERROR)
  list(APPEND RDSF_WARNING_FLAGS -Werror)
endif()

function(rdsf_add_warnings_in directory)
  get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target ${targets})
    get_target_property(type ${target} TYPE)
    if(type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY)$")
      target_compile_options(${target} PRIVATE ${RDSF_WARNING_FLAGS})
    endif()
  endforeach()
  get_property(subdirectories DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
  foreach(subdirectory ${subdirectories})
    rdsf_add_warnings_in(${subdirectory})
  endforeach()
endfunction()
cmake_language(DEFER DIRECTORY ${PROJECT_SOURCE_DIR} CALL rdsf_add_warnings_in ${PROJECT_SOURCE_DIR})
