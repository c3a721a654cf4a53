# Installs the public headers under <includedir>/furrow/ so that a consumer
# includes them as <furrow/geometry/part.hpp>, with only <includedir> on its
# include path: generic top-level names such as "geometry/" or "io/" would
# collide with a consumer's own folders. Inside the project the headers
# include one another as "geometry/part.hpp" (src/ is the build's include
# folder); here each such include of a Furrow module becomes
# "furrow/geometry/part.hpp", so the installed tree needs nothing else on the
# path. Run by install(CODE ...) with FURROW_SOURCE_ROOT (the src/ folder),
# FURROW_HEADER_MODULES (the top-level module folders), FURROW_HEADER_EXCLUDE
# (regular expressions of paths below src/ that are internal) and
# FURROW_INCLUDE_DESTINATION (<includedir>, relative or absolute).
if(IS_ABSOLUTE "${FURROW_INCLUDE_DESTINATION}")
  set(destination "$ENV{DESTDIR}${FURROW_INCLUDE_DESTINATION}/furrow")
else()
  set(destination "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}/${FURROW_INCLUDE_DESTINATION}/furrow")
endif()
list(JOIN FURROW_HEADER_MODULES "|" modules)
file(GLOB_RECURSE headers RELATIVE "${FURROW_SOURCE_ROOT}" "${FURROW_SOURCE_ROOT}/*.hpp")
list(SORT headers)
set(count 0)
foreach(header IN LISTS headers)
  set(internal FALSE)
  foreach(pattern IN LISTS FURROW_HEADER_EXCLUDE)
    if(header MATCHES "${pattern}")
      set(internal TRUE)
    endif()
  endforeach()
  if(internal)
    continue()
  endif()
  file(READ "${FURROW_SOURCE_ROOT}/${header}" text)
  string(REGEX REPLACE "#include \"(${modules})/" "#include \"furrow/\\1/" text "${text}")
  set(target "${destination}/${header}")
  # Unchanged files keep their time stamp, as install(FILES) does.
  set(old "")
  if(EXISTS "${target}")
    file(READ "${target}" old)
  endif()
  if(NOT old STREQUAL text)
    file(WRITE "${target}" "${text}")
  endif()
  math(EXPR count "${count} + 1")
endforeach()
message(STATUS "Installed ${count} public headers in ${destination} (included as <furrow/...>)")
