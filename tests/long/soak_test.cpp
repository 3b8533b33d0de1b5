// The long soak (label `long`, part of `make test` in Release; not under the sanitizers):
// over a million random local operations (every op of the sweep) across the sweep corpus and the
// pillow family with validate() after every one, and 10,000 random editor commands whose undo and
// redo must equal a model's, bit for bit.

#include <gtest/gtest.h>

#include "core/op_sweep.h"
#include "viewer/undo_sweep.h"

namespace meshedit {
namespace {

TEST(Soak, AMillionRandomOperations) {
    std::vector<test::NamedMesh> meshes = test::sweep_corpus();
    for (auto& shape : test::pillow_family()) {
        meshes.push_back(std::move(shape));
    }
    test::Tally tally;
    constexpr long kOps = 1'000'000;
    const long per_run = kOps / static_cast<long>(2 * meshes.size()) + 1;
    for (const auto& shape : meshes) {
        for (unsigned seed : {101u, 202u}) {
            test::sweep(shape, seed + static_cast<unsigned>(shape.name.size()), per_run, tally);
            if (HasFatalFailure()) {
                return;
            }
        }
    }
    EXPECT_GE(tally.ops, kOps);
    for (std::size_t k = 0; k < test::sweep_ops().size(); ++k) {
        EXPECT_GT(tally.applied[k], 0) << test::sweep_ops()[k].name;
        RecordProperty(std::string(test::sweep_ops()[k].name), std::to_string(tally.applied[k]));
    }
    for (const char* op : {"flip", "split", "collapse"}) {
        EXPECT_GT(tally.applied_of(op), tally.ops / 20) << op;
    }
    RecordProperty("ops", std::to_string(tally.ops));
}

TEST(Soak, TenThousandEditorCommandsUndoBitForBit) {
    viewer::Sweep sweep(77u);
    sweep.run(10000);
    ASSERT_FALSE(HasFatalFailure());
    EXPECT_GT(sweep.edits(), 2000u);
    EXPECT_GT(sweep.undos(), 500u);
    sweep.unwind_and_replay();
}

}  // namespace
}  // namespace meshedit
