# Every Markdown file that a source comment cites (a path ending in .md) exists in the
# repository, at that path from its root: the notes the code relies on travel with it.
# Run with -DSOURCE_DIR=<the repository's root>.
file(GLOB_RECURSE sources RELATIVE "${SOURCE_DIR}"
     "${SOURCE_DIR}/Tools/*.h" "${SOURCE_DIR}/Tools/*.cpp"
     "${SOURCE_DIR}/ThyrixLite/*.h" "${SOURCE_DIR}/ThyrixLite/*.cpp"
     "${SOURCE_DIR}/ThyrixPro/*.h" "${SOURCE_DIR}/ThyrixPro/*.cpp"
     "${SOURCE_DIR}/Controller/*.h" "${SOURCE_DIR}/Controller/*.cpp"
     "${SOURCE_DIR}/Agents/*.h" "${SOURCE_DIR}/Agents/*.cpp"
     "${SOURCE_DIR}/Evolution/*.h" "${SOURCE_DIR}/Evolution/*.cpp"
     "${SOURCE_DIR}/GUIWx/*.h" "${SOURCE_DIR}/GUIWx/*.cpp"
     "${SOURCE_DIR}/examples/*.h" "${SOURCE_DIR}/examples/*.cpp"
     "${SOURCE_DIR}/scenes/*.h" "${SOURCE_DIR}/scenes/*.cpp"
     "${SOURCE_DIR}/bench/*.h" "${SOURCE_DIR}/bench/*.cpp"
     "${SOURCE_DIR}/fuzz/*.cpp" "${SOURCE_DIR}/python/src/*.h" "${SOURCE_DIR}/python/src/*.cpp")
set(checked 0)
set(missing "")
foreach(source IN LISTS sources)
  file(STRINGS "${SOURCE_DIR}/${source}" lines REGEX "[A-Za-z0-9_]\\.md")
  foreach(line IN LISTS lines)
    string(REGEX MATCHALL "[A-Za-z0-9_./-]+\\.md" cited "${line}")
    foreach(path IN LISTS cited)
      math(EXPR checked "${checked} + 1")
      if(NOT EXISTS "${SOURCE_DIR}/${path}")
        list(APPEND missing "${source} cites ${path}")
      endif()
    endforeach()
  endforeach()
endforeach()
if(checked EQUAL 0)
  message(FATAL_ERROR "no citation of a .md file found: the check reads nothing")
endif()
if(missing)
  list(JOIN missing "\n  " text)
  message(FATAL_ERROR "cited notes missing from the repository:\n  ${text}")
endif()
message(STATUS "${checked} citations of notes, each a file of the repository")
