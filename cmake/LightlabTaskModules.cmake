# Task modules: each task's file compiled into its own shared object, lightlab_<ID>.so, that
# the programs load at run time (framework/tasks/task_modules.h). Used by the main build
# (assignments/CMakeLists.txt) and by the autograder's module build (cmake/task_modules/),
# so a submission's modules are compiled exactly as the student's own build compiles them.
# Needs LIGHTLAB_ROOT (the source tree), the task catalog (LightlabTasks.cmake), the
# lightlab_warnings target, glm, nlohmann_json and TBB.
#
#   lightlab_task_module(TARGET ID OUTPUT_DIR SOLUTION_VALUE [SOURCE FILE] [CHECK_WITH PROGRAM])
#
# CHECK_WITH: after linking, PROGRAM (lightlab) checks the module: every symbol it uses must be
# defined and open to student code, and it may export nothing but its entry -- so no student
# file can define a framework or grader symbol. A module that fails the check is deleted.

# Compile settings of every task module: the framework's and the assignments' headers,
# nothing linked (the module's calls resolve against the program that loads it), and
# every symbol hidden but the generated entry (cmake/task_module_entry.cpp.in).
add_library(lightlab_module_settings INTERFACE)
target_include_directories(lightlab_module_settings INTERFACE
  ${LIGHTLAB_ROOT}/framework
  $<TARGET_PROPERTY:TBB::tbb,INTERFACE_INCLUDE_DIRECTORIES>)
foreach(id IN LISTS LIGHTLAB_TASK_IDS)
  string(REPLACE "." "_" key ${id})
  target_include_directories(lightlab_module_settings INTERFACE ${LIGHTLAB_ROOT}/assignments/${LIGHTLAB_TASK_${key}_FOLDER})
endforeach()
target_link_libraries(lightlab_module_settings INTERFACE glm::glm nlohmann_json::nlohmann_json lightlab_warnings)
target_compile_options(lightlab_module_settings INTERFACE -fvisibility=hidden -fvisibility-inlines-hidden)

# ccache calls every compile that makes or uses a precompiled header uncacheable unless these of its
# checks are relaxed (the header's defines, __TIME__, the times of headers this build writes); without
# them every build, and every grading, compiled the modules anew (6 s a grading). Set on the targets
# below only, so they hold however the build is started (CI, the autograder, a student's cmake --build).
function(lightlab_pch_launcher target)
  if(CMAKE_CXX_COMPILER_LAUNCHER MATCHES "ccache")
    set_target_properties(${target} PROPERTIES CXX_COMPILER_LAUNCHER
      "${CMAKE_COMMAND};-E;env;CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime;${CMAKE_CXX_COMPILER_LAUNCHER}")
  endif()
endfunction()

# One precompiled header for every student module (cmake/task_module_pch.h: the framework
# headers the task headers include), so a module's compile is the student's file alone: what
# the GUI's hot reload waits for after a save (a one-line change: about 1.3 s -> 0.4 s).
# Compiled with exactly the student modules' flags (LIGHTLAB_SOLUTION=0, PIC, no export macro).
add_library(lightlab_module_pch OBJECT ${LIGHTLAB_ROOT}/cmake/task_module_pch.cpp)
target_link_libraries(lightlab_module_pch PRIVATE lightlab_module_settings)
target_compile_definitions(lightlab_module_pch PRIVATE LIGHTLAB_SOLUTION=0)
set_target_properties(lightlab_module_pch PROPERTIES POSITION_INDEPENDENT_CODE ON EXCLUDE_FROM_ALL ON)
target_precompile_headers(lightlab_module_pch PRIVATE ${LIGHTLAB_ROOT}/cmake/task_module_pch.h)
lightlab_pch_launcher(lightlab_module_pch)

# The module of task ID from its file (assignments/<folder>/<file>, or SOURCE).
function(lightlab_task_module target id output_dir solution)
  cmake_parse_arguments(ARG "" "SOURCE;CHECK_WITH" "" ${ARGN})
  string(REPLACE "." "_" key ${id})
  set(folder ${LIGHTLAB_TASK_${key}_FOLDER})
  set(file ${LIGHTLAB_TASK_${key}_FILE})
  string(REGEX REPLACE "^A([0-9]+)\\..*" "a\\1" ns ${id})
  set(TASK_ID ${id})
  set(TASK_FILE ${folder}/${file})
  set(TASK_HEADER ${ns}_tasks.h)
  set(TASK_LOOKUPS "")
  foreach(f IN LISTS LIGHTLAB_TASK_${key}_FUNCTIONS)
    string(APPEND TASK_LOOKUPS
      "  if (std::strcmp(name, \"${f}\") == 0) return reinterpret_cast<void*>(&ll::${ns}::${f});\n")
  endforeach()
  set(entry ${CMAKE_BINARY_DIR}/generated/modules/entry_${key}.cpp)
  configure_file(${LIGHTLAB_ROOT}/cmake/task_module_entry.cpp.in ${entry} @ONLY)
  set(source ${LIGHTLAB_ROOT}/assignments/${folder}/${file})
  if(ARG_SOURCE)
    set(source ${ARG_SOURCE})
  endif()
  add_library(${target} MODULE ${source} ${entry})
  target_link_libraries(${target} PRIVATE lightlab_module_settings)
  target_compile_definitions(${target} PRIVATE LIGHTLAB_SOLUTION=${solution})
  set_target_properties(${target} PROPERTIES PREFIX "" OUTPUT_NAME lightlab_${id}
                        LIBRARY_OUTPUT_DIRECTORY ${output_dir})
  if(solution STREQUAL "0")  # a student module: the shared precompiled header
    set_target_properties(${target} PROPERTIES DEFINE_SYMBOL "")
    target_precompile_headers(${target} REUSE_FROM lightlab_module_pch)
    lightlab_pch_launcher(${target})
  endif()
  if(ARG_CHECK_WITH)
    add_custom_command(TARGET ${target} POST_BUILD
      COMMAND ${CMAKE_COMMAND} -DPROGRAM=${ARG_CHECK_WITH} -DMODULE=$<TARGET_FILE:${target}> -DTASK=${id}
              -P ${LIGHTLAB_ROOT}/cmake/check_task_module.cmake
      VERBATIM)
  endif()
endfunction()

