#include "dynamic_library.hpp"

#include <dlfcn.h>

#include "mink/render/render_error.hpp"

namespace mink::detail {

DynamicLibrary::DynamicLibrary(std::initializer_list<const char*> names, std::string_view purpose) {
  std::string tried;
  std::string last_error;
  for (const char* name : names) {
    handle_ = dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (handle_ != nullptr) {
      name_ = name;
      return;
    }
    if (!tried.empty()) tried += ", ";
    tried += name;
    const char* error = dlerror();
    last_error = error != nullptr ? error : "unknown error";
  }
  throw GlContextError(std::string(purpose) + ": cannot open " + tried + " (" + last_error + ")");
}

void* DynamicLibrary::symbol(const char* symbol) const {
  void* address = dlsym(handle_, symbol);
  if (address == nullptr) {
    throw GlContextError(name_ + " has no symbol " + symbol);
  }
  return address;
}

bool has_extension(const char* list, std::string_view name) {
  if (list == nullptr) return false;
  std::string_view rest(list);
  while (!rest.empty()) {
    const std::size_t space = rest.find(' ');
    if (rest.substr(0, space) == name) return true;
    if (space == std::string_view::npos) break;
    rest.remove_prefix(space + 1);
  }
  return false;
}

}  // namespace mink::detail
