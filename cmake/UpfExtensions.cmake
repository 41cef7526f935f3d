# Extensions: solvers and material kinds compiled into the `upf` program from folders outside
# framework/, solvers/ and materials/ (docs/extending.md).
#
# The cache list UPF_EXTENSION_DIRS names the folders (relative to the source root, or absolute
# for a folder outside the repository). Each folder's CMakeLists.txt builds a library and calls
#
#   upf_add_extension(TARGET <library> REGISTER <function>)
#
# where <function> is `void <function>(upf::Registry&)`, possibly namespace-qualified
# (`upf::pbf::register_pbf`). The `upf` program links every such library and calls every such
# function, in the order of UPF_EXTENSION_DIRS, right after the built-ins
# (apps/upf/app_registry.cpp calls the generated register_extensions()). Registration stays an
# explicit function call: no static initialisers, no global registry.

# Adds every folder of `dirs` as a subdirectory. Called once from the root CMakeLists.txt, after
# framework/, materials/ and solvers/ (extensions link them) and before apps/upf (which links
# the extensions).
function(upf_add_extension_dirs dirs)
  set(_seen "")
  foreach(_dir IN LISTS dirs)
    if(IS_ABSOLUTE "${_dir}")
      set(_source "${_dir}")
    else()
      set(_source "${PROJECT_SOURCE_DIR}/${_dir}")
    endif()
    if(NOT EXISTS "${_source}/CMakeLists.txt")
      message(FATAL_ERROR "UPF_EXTENSION_DIRS: '${_dir}' has no CMakeLists.txt (looked in ${_source})")
    endif()
    # A binary folder per extension, named after its source folder: add_subdirectory needs one
    # for a folder outside the source tree.
    get_filename_component(_name "${_source}" NAME)
    if(_name IN_LIST _seen)
      message(FATAL_ERROR "UPF_EXTENSION_DIRS: two extension folders are named '${_name}'; rename one")
    endif()
    list(APPEND _seen "${_name}")
    add_subdirectory("${_source}" "${PROJECT_BINARY_DIR}/extensions/${_name}")
  endforeach()
endfunction()

# Called by an extension folder: the `upf` program links TARGET and calls REGISTER.
function(upf_add_extension)
  cmake_parse_arguments(PARSE_ARGV 0 ARG "" "TARGET;REGISTER" "")
  if(ARG_UNPARSED_ARGUMENTS OR NOT ARG_TARGET OR NOT ARG_REGISTER)
    message(FATAL_ERROR "usage: upf_add_extension(TARGET <library> REGISTER <function>)")
  endif()
  if(NOT TARGET "${ARG_TARGET}")
    message(FATAL_ERROR "upf_add_extension: '${ARG_TARGET}' is not a target; add_library it first")
  endif()
  if(NOT ARG_REGISTER MATCHES "^[A-Za-z_][A-Za-z0-9_]*(::[A-Za-z_][A-Za-z0-9_]*)*$")
    message(FATAL_ERROR "upf_add_extension: REGISTER '${ARG_REGISTER}' is not a C++ function name")
  endif()
  get_property(_sealed GLOBAL PROPERTY UPF_EXTENSIONS_SEALED)
  if(_sealed)
    message(FATAL_ERROR "upf_add_extension(${ARG_TARGET}) comes after the upf program was "
                        "configured; list the folder in UPF_EXTENSION_DIRS instead")
  endif()
  set_property(GLOBAL APPEND PROPERTY UPF_EXTENSION_TARGETS "${ARG_TARGET}")
  set_property(GLOBAL APPEND PROPERTY UPF_EXTENSION_FUNCTIONS "${ARG_REGISTER}")
endfunction()

# Writes `output`, a C++ source defining upf::app::register_extensions(Registry&) that calls
# every registered function, and sets `targets_var` to the extension libraries to link.
function(upf_generate_extension_registry output targets_var)
  set_property(GLOBAL PROPERTY UPF_EXTENSIONS_SEALED TRUE)
  get_property(_targets GLOBAL PROPERTY UPF_EXTENSION_TARGETS)
  get_property(_functions GLOBAL PROPERTY UPF_EXTENSION_FUNCTIONS)
  set(UPF_EXTENSION_DECLARATIONS "")
  set(UPF_EXTENSION_CALLS "")
  foreach(_function IN LISTS _functions)
    # `a::b::f` is declared as `namespace a::b { void f(upf::Registry&); }`.
    string(FIND "${_function}" "::" _split REVERSE)
    if(_split EQUAL -1)
      string(APPEND UPF_EXTENSION_DECLARATIONS "void ${_function}(upf::Registry& registry);\n")
    else()
      string(SUBSTRING "${_function}" 0 ${_split} _namespace)
      math(EXPR _start "${_split} + 2")
      string(SUBSTRING "${_function}" ${_start} -1 _name)
      string(APPEND UPF_EXTENSION_DECLARATIONS
             "namespace ${_namespace} {\nvoid ${_name}(upf::Registry& registry);\n}\n")
    endif()
    string(APPEND UPF_EXTENSION_CALLS "  ::${_function}(registry);\n")
  endforeach()
  configure_file("${PROJECT_SOURCE_DIR}/cmake/app_extensions.cpp.in" "${output}" @ONLY)
  set(${targets_var} "${_targets}" PARENT_SCOPE)
endfunction()
