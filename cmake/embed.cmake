# Embeds shaders/ and scenarios/*.json into the binary so `sylva` runs from anywhere and the
# default scenario needs no file. Lookup: sylva::embedded_file("shaders/terrain.vert").
function(sylva_embed out_var)
  set(files)
  foreach(dir ${ARGN})
    file(GLOB_RECURSE found CONFIGURE_DEPENDS ${dir}/*.glsl ${dir}/*.vert ${dir}/*.frag
         ${dir}/*.geom ${dir}/*.comp ${dir}/*.json)
    list(APPEND files ${found})
  endforeach()
  list(SORT files)
  set(out ${CMAKE_BINARY_DIR}/embedded/embedded_files.cpp)
  # The file list travels in a file: a CMake list on a command line would be split by the shell.
  set(list_file ${CMAKE_BINARY_DIR}/embedded/embedded_files.txt)
  file(WRITE ${list_file}.tmp "${files}")
  file(COPY_FILE ${list_file}.tmp ${list_file} ONLY_IF_DIFFERENT)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DROOT=${CMAKE_SOURCE_DIR} -DLIST_FILE=${list_file}
            -P ${CMAKE_SOURCE_DIR}/cmake/embed_files.cmake
    DEPENDS ${files} ${list_file} ${CMAKE_SOURCE_DIR}/cmake/embed_files.cmake
    VERBATIM
    COMMENT "Embedding shaders and scenarios")
  set(${out_var} ${out} PARENT_SCOPE)
endfunction()
