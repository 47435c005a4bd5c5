# GL 4.5 core loader generated at configure time by Debian's python3-glad (glad 2), from the
# Khronos XML it ships (--reproducible: no network).
find_program(GLAD_EXECUTABLE glad REQUIRED)
set(SYLVA_GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
if(NOT EXISTS ${SYLVA_GLAD_DIR}/src/gl.c)
  execute_process(
    COMMAND ${GLAD_EXECUTABLE} --quiet --reproducible --api gl:core=4.5 --out-path ${SYLVA_GLAD_DIR} c
    RESULT_VARIABLE glad_result OUTPUT_QUIET ERROR_VARIABLE glad_error)
  if(NOT glad_result EQUAL 0)
    message(FATAL_ERROR "glad failed to generate the GL 4.5 loader: ${glad_error}")
  endif()
endif()
add_library(sylva_glad STATIC ${SYLVA_GLAD_DIR}/src/gl.c)
target_include_directories(sylva_glad SYSTEM PUBLIC ${SYLVA_GLAD_DIR}/include)
set_target_properties(sylva_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
target_link_libraries(sylva_glad PUBLIC ${CMAKE_DL_LIBS})
