// The acceptance sweep: across a random sequence of 1,000 commands (selections, flip,
// split, collapse, crease, Loop, vertex drags, navigation, undo, redo) the mesh stays valid,
// every edit equals the direct core operation, refusals change nothing, and undo/redo return
// the document bit for bit to each earlier state. A model keeps its own undo and redo stacks
// of expected documents with the same semantics; at the end everything is undone back to
// the start and redone to the end, state by state.

#include "viewer/undo_sweep.h"

namespace meshedit::viewer {
namespace {

TEST(UndoSweep, ThousandRandomCommandsUndoBitForBit) {
    Sweep sweep(20240611u);
    sweep.run(1000);
    ASSERT_FALSE(::testing::Test::HasFatalFailure());
    // The sequence must exercise what it claims to.
    EXPECT_GT(sweep.edits(), 200u);
    EXPECT_GT(sweep.refusals(), 10u);
    EXPECT_GT(sweep.undos(), 50u);
    EXPECT_GE(sweep.loops(), 2u);
    EXPECT_GT(sweep.drags(), 20u);
    EXPECT_GT(sweep.modals(), 10u);
    sweep.unwind_and_replay();
}

}  // namespace
}  // namespace meshedit::viewer
