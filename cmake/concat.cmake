# Concatenates the files PARTS (a list, in order) into OUT, written only when its text changes
# (python/CMakeLists.txt: the bindings' stubs, one file a concept, into _inerta.pyi).
set(text "")
foreach(part ${PARTS})
  file(READ ${part} piece)
  string(APPEND text "${piece}")
endforeach()
if(EXISTS ${OUT})
  file(READ ${OUT} old)
  if(old STREQUAL text)
    return()
  endif()
endif()
file(WRITE ${OUT} "${text}")
