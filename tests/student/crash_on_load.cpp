// A student library that crashes while it is being loaded: a global's initialiser follows a
// null pointer. The grader must say so without going down itself.

namespace {

int* volatile nowhere = nullptr;
const int first = *nowhere;

}  // namespace

int crash_on_load_value() {
    return first;
}
