# Finds wxWidgets 3.2 (core, base) and makes the imported target wxWidgets::wxWidgets, which
# CMake's FindwxWidgets provides only from CMake 3.27 on. Used by GUIWx/ and, once installed, by
# ThyrixConfig.cmake so that a consumer of thyrix::GUIWx gets wx's flags the same way. Does
# nothing (and leaves the target undefined) when wxWidgets is not found.
if(NOT TARGET wxWidgets::wxWidgets)
  find_package(wxWidgets 3.2 QUIET COMPONENTS core base)
  if(wxWidgets_FOUND)
    add_library(wxWidgets::wxWidgets INTERFACE IMPORTED)
    # Imported include directories are SYSTEM: wx's headers do not trip -Wconversion and friends.
    set_target_properties(wxWidgets::wxWidgets PROPERTIES
      INTERFACE_INCLUDE_DIRECTORIES "${wxWidgets_INCLUDE_DIRS}"
      INTERFACE_COMPILE_DEFINITIONS "${wxWidgets_DEFINITIONS}"
      INTERFACE_COMPILE_OPTIONS "${wxWidgets_CXX_FLAGS}"
      INTERFACE_LINK_LIBRARIES "${wxWidgets_LIBRARIES}")
  endif()
endif()
