#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

namespace mink::detail {

// A shared library opened once per process and kept open: GL drivers do not like being
// unloaded while their threads or atexit handlers still refer to them.
class DynamicLibrary {
 public:
  // Tries each name in turn; throws GlContextError naming them all (and `purpose`) when none
  // opens.
  DynamicLibrary(std::initializer_list<const char*> names, std::string_view purpose);
  // Address of `symbol`; throws GlContextError naming it when missing.
  void* symbol(const char* symbol) const;
  template <typename Function>
  Function function(const char* name) const {
    return reinterpret_cast<Function>(symbol(name));
  }

 private:
  void* handle_ = nullptr;
  std::string name_;
};

// True when the space-separated `list` holds `name` as a whole word.
bool has_extension(const char* list, std::string_view name);

}  // namespace mink::detail
