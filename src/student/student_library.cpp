// The one dlopen() of student code.

#include "student_library.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace meshedit::cli::grade {

const student::StudentTasks& load_student_library(const std::filesystem::path& path) {
    // dlopen() searches the library path for a bare name; a file here is meant.
    const std::string name = path.has_parent_path() ? path.string() : "./" + path.string();
    void* handle = ::dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
        throw std::runtime_error("cannot load " + path.string() + ": " + ::dlerror());
    }
    using Entry = const student::StudentTasks* (*)();
    const auto entry = reinterpret_cast<Entry>(::dlsym(handle, MESHEDIT_STUDENT_ENTRY));
    if (entry == nullptr) {
        throw std::runtime_error(path.string() + " does not export " MESHEDIT_STUDENT_ENTRY
                                                 "() (one .cpp of it says "
                                                 "MESHEDIT_STUDENT_REGISTER())");
    }
    const student::StudentTasks* tasks = entry();
    if (tasks == nullptr || tasks->abi_version != student::kStudentAbiVersion) {
        throw std::runtime_error(path.string() + " was built against student API version " +
                                 (tasks ? std::to_string(tasks->abi_version) : "?") +
                                 ", this meshedit has version " +
                                 std::to_string(student::kStudentAbiVersion) + ": rebuild it");
    }
    return *tasks;
}

}  // namespace meshedit::cli::grade
