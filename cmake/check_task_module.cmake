# cmake -DPROGRAM=lightlab -DMODULE=lightlab_A2.3.so -DTASK=A2.3 -P check_task_module.cmake
# Runs `lightlab check-module` on a freshly linked task module; a module that fails the check
# is deleted (so a failed build leaves nothing to load) and the build step fails with its messages.
execute_process(COMMAND ${PROGRAM} --quiet check-module ${MODULE} --task ${TASK} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  file(REMOVE ${MODULE})
  message(FATAL_ERROR "task module ${TASK} rejected (above); fix the file and build again")
endif()
