// Whole-mesh operations in the background (editor.h): the worker runs the verb on its own copy
// of the mesh, so the document the window draws and hovers is never half built, and a cancel
// only has to throw the copy away. The document takes no command that would change it while
// the worker runs: its result replaces the mesh the worker copied, nothing else.

#include <atomic>
#include <chrono>
#include <exception>
#include <new>
#include <thread>

#include "meshedit/viewer/editor.h"

namespace meshedit::viewer {

namespace {

/// Thrown from the progress report once Esc asked the operation to stop.
struct Cancelled {};

}  // namespace

struct Editor::Job {
    const ops::Verb* verb = nullptr;
    ops::Step step;
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
    std::atomic<double> fraction{0.0};
    std::atomic<bool> cancel{false};
    std::atomic<bool> done{false};  ///< the fields below are written; release/acquire
    std::optional<Mesh> result;
    ops::StepResult step_result;
    std::optional<GarbageCollectionMap> compacted;
    std::string error;  ///< why it could not run (an exception's text)
    bool cancelled = false;
    std::jthread worker;  ///< last: joined before the fields it writes go

    void run(const Mesh& source) {
        try {
            Mesh work = source;  // the document takes no edit while this runs
            ops::RunOptions options;
            options.progress = [this](double f) {
                fraction.store(f, std::memory_order_relaxed);
                if (cancel.load(std::memory_order_relaxed)) {
                    throw Cancelled{};
                }
            };
            step_result = verb->run(work, step, options);
            if (cancel.load()) {
                throw Cancelled{};
            }
            // The garbage collection edit() would do after it, here rather than on the UI
            // thread; the selection is remapped when the result goes in.
            if (work.has_garbage()) {
                compacted.emplace();
                work.garbage_collection(&*compacted);
            }
            result = std::move(work);
        } catch (const Cancelled&) {
            cancelled = true;
        } catch (const std::bad_alloc&) {
            error = "not enough memory: nothing changed";
        } catch (const std::exception& e) {
            error = e.what();
        }
        done.store(true, std::memory_order_release);
    }
};

// Here, where Job is complete (its unique_ptr's deleter).
Editor::Editor(HistoryLimits limits) : ledger_(limits) {}
Editor::Editor(Editor&&) noexcept = default;
Editor& Editor::operator=(Editor&&) noexcept = default;

Editor::~Editor() {
    if (job_) {
        job_->cancel = true;  // the jthread joins as job_ goes
    }
}

Outcome Editor::start_job(const ops::Verb& verb, ops::Step step) {
    end_drag();
    diagram_.reset();
    job_ = std::make_unique<Job>();
    Job& job = *job_;
    job.verb = &verb;
    job.step = std::move(step);
    job.worker = std::jthread([&job, &mesh = doc_.mesh] { job.run(mesh); });
    return {kJobStarted | kDisplay,
            std::string(verb.name) + " running — you can orbit meanwhile; Esc cancels"};
}

std::optional<Editor::JobProgress> Editor::job_progress() const {
    if (!job_) {
        return std::nullopt;
    }
    return JobProgress{
        std::string(job_->verb->name), job_->fraction.load(std::memory_order_relaxed),
        std::chrono::duration<double>(std::chrono::steady_clock::now() - job_->started).count()};
}

Outcome Editor::cancel_job() {
    if (!job_) {
        return {};
    }
    job_->cancel = true;
    return {kDisplay, "cancelling " + std::string(job_->verb->name) + "…"};
}

std::optional<Outcome> Editor::wait_job() {
    if (!job_) {
        return std::nullopt;
    }
    job_->worker.join();
    return finish_job();
}

std::optional<Outcome> Editor::finish_job() {
    if (!job_ || !job_->done.load(std::memory_order_acquire)) {
        return std::nullopt;
    }
    const std::unique_ptr<Job> job = std::move(job_);
    if (job->worker.joinable()) {
        job->worker.join();
    }
    const std::string name(job->verb->name);
    if (job->cancelled) {
        return Outcome{kDisplay, name + " cancelled: nothing changed"};
    }
    if (!job->result) {
        return refused(job->error);
    }
    Transaction transaction(ledger_, doc_, std::move(*job->result));
    Edited edited = after_whole_mesh(job->step_result, job->step.text);
    settle(edited);
    if (job->compacted) {
        remap_selection(*job->compacted);
        edited.steps.emplace_back("compact");
    }
    return transaction.commit(edited.changes, std::move(edited.message), std::move(edited.steps));
}

std::optional<Outcome> Editor::refuse_if_busy() const {
    if (!job_) {
        return std::nullopt;
    }
    return refused(std::string(job_->verb->name) +
                   " is running: wait for it, or press Esc to cancel it");
}

}  // namespace meshedit::viewer
