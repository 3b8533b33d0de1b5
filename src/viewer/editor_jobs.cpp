// Long operations in the background (editor.h): whole-mesh verbs, opening and saving. A verb
// runs on its own copy of the mesh, so the document the window draws and hovers is never
// half built, and a cancel only has to throw the copy away. The document takes no command
// that would change it while the worker runs; the result is put in on the UI thread.

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <new>
#include <thread>

#include "meshedit/viewer/editor.h"

namespace meshedit::viewer {

namespace {

/// Thrown from the progress report once Esc asked the operation to stop.
struct Cancelled {};

}  // namespace

struct Editor::Job {
    std::string label;      ///< "simplify", "open bunny.ply"
    bool stoppable = true;  ///< Esc stops it (a save runs to the end: its file is atomic)
    bool measured = true;   ///< it reports progress
    /// On the worker: does the work, calling progress(); throws to refuse.
    std::function<void(Job&)> work;
    /// On the UI thread, once `work` returned: puts the result in.
    std::function<Outcome()> finish;
    std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
    std::atomic<double> fraction{0.0};
    std::atomic<bool> cancel{false};
    std::atomic<bool> done{false};  ///< what the worker wrote is complete; release/acquire
    std::string error;              ///< why it could not run (an exception's text)
    bool cancelled = false;
    std::jthread worker;  ///< last: joined before the fields it writes go

    void progress(double f) {
        fraction.store(f, std::memory_order_relaxed);
        if (stoppable && cancel.load(std::memory_order_relaxed)) {
            throw Cancelled{};
        }
    }

    void run() {
        try {
            work(*this);
            if (stoppable && cancel.load()) {
                throw Cancelled{};  // an open that could not be interrupted: its result goes
            }
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

Outcome Editor::start_job(std::string label, bool stoppable, bool measured,
                          std::function<void(Job&)> work, std::function<Outcome()> finish) {
    end_drag();
    diagram_.reset();
    job_ = std::make_unique<Job>();
    Job& job = *job_;
    job.label = std::move(label);
    job.stoppable = stoppable;
    job.measured = measured;
    job.work = std::move(work);
    job.finish = std::move(finish);
    job.worker = std::jthread([&job] { job.run(); });
    return {kJobStarted | kDisplay, job.label + " running" + (stoppable ? " — Esc cancels" : "")};
}

Outcome Editor::start_job(const ops::Verb& verb, ops::Step step) {
    struct Result {
        std::optional<Mesh> mesh;
        ops::StepResult step;
        std::optional<GarbageCollectionMap> compacted;
    };
    auto result = std::make_shared<Result>();
    auto work = [result, &verb, step, &source = doc_.mesh](Job& job) {
        Mesh mesh = source;  // the document takes no edit while this runs
        ops::RunOptions options;
        options.progress = [&job](double f) { job.progress(f); };
        result->step = verb.run(mesh, step, options);
        job.progress(1.0);
        // The garbage collection edit() would do after it, here rather than on the UI
        // thread; the selection is remapped when the result goes in.
        if (mesh.has_garbage()) {
            result->compacted.emplace();
            mesh.garbage_collection(&*result->compacted);
        }
        result->mesh = std::move(mesh);
    };
    auto finish = [this, result, text = step.text] {
        Transaction transaction(ledger_, doc_, std::move(*result->mesh));
        Edited edited = after_whole_mesh(result->step, text);
        settle(edited);
        if (result->compacted) {
            remap_selection(*result->compacted);
            edited.steps.emplace_back("compact");
        }
        return transaction.commit(edited.changes, std::move(edited.message),
                                  std::move(edited.steps));
    };
    return start_job(std::string(verb.name), true, true, std::move(work), std::move(finish));
}

std::optional<Editor::JobProgress> Editor::job_progress() const {
    if (!job_) {
        return std::nullopt;
    }
    return JobProgress{
        job_->label, job_->measured ? job_->fraction.load(std::memory_order_relaxed) : -1.0,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - job_->started).count()};
}

Outcome Editor::cancel_job() {
    if (!job_) {
        return {};
    }
    if (!job_->stoppable) {
        return {kDisplay, job_->label + " cannot stop halfway: it ends in a moment"};
    }
    job_->cancel = true;
    return {kDisplay, "cancelling " + job_->label + "…"};
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
    if (job->cancelled) {
        return Outcome{kDisplay, job->label + " cancelled: nothing changed"};
    }
    if (!job->error.empty()) {
        return refused(job->error);
    }
    return job->finish();
}

std::optional<Outcome> Editor::refuse_if_busy() const {
    if (!job_) {
        return std::nullopt;
    }
    return refused(job_->label + " is running: wait for it" +
                   (job_->stoppable ? ", or press Esc to cancel it" : ""));
}

}  // namespace meshedit::viewer
