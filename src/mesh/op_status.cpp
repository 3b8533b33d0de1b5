// Composed refusal texts live in one set for the rest of the program, so an OpStatus stays
// two pointers whatever made its reason. Refusals are few and repeat (a user presses the key
// again; a fuzzer's texts draw on a few numbers), so the set stays small.

#include "meshedit/core/op_status.h"

#include <mutex>
#include <ostream>
#include <unordered_set>

namespace meshedit {

OpStatus OpStatus::composed(const std::string& reason) {
    if (reason.empty()) {
        return ok();
    }
    static std::mutex mutex;
    static std::unordered_set<std::string>* texts = new std::unordered_set<std::string>();
    const std::lock_guard lock(mutex);
    return refused(*texts->insert(reason).first);  // nodes never move: the view stays valid
}

std::ostream& operator<<(std::ostream& out, const OpStatus& status) {
    return status ? out << "ok" : out << status.reason();
}

}  // namespace meshedit
