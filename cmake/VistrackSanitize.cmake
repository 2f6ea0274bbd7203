# VISTRACK_SANITIZE: a comma-separated list of GCC/Clang sanitizers for every target of this
# project (core library, extension, tests, apps), e.g. -DVISTRACK_SANITIZE=address,undefined
# (scripts/sanitize.sh builds and runs that). Undefined behaviour is fatal (no recovery), so a
# finding fails the test that triggers it. Dependencies (Embree, TBB, CGAL's compiled parts,
# GoogleTest, Python) stay uninstrumented: ASan still sees their heap through its malloc.
set(VISTRACK_SANITIZE "" CACHE STRING "Sanitizers for vistrack's targets, e.g. address,undefined (empty: none)")
if(VISTRACK_SANITIZE)
  set(_vistrack_sanitize_flags -fsanitize=${VISTRACK_SANITIZE} -fno-omit-frame-pointer)
  if(VISTRACK_SANITIZE MATCHES "undefined")
    # vptr checks need RTTI of every class a pointer may hold across the uninstrumented libraries
    # (pybind11 casts Python-owned objects): they report types, not bugs. Everything else is fatal.
    list(APPEND _vistrack_sanitize_flags -fno-sanitize=vptr -fno-sanitize-recover=all)
  endif()
  add_compile_options(${_vistrack_sanitize_flags})
  add_link_options(-fsanitize=${VISTRACK_SANITIZE})
  message(STATUS "vistrack: sanitizers ${VISTRACK_SANITIZE}")
endif()
