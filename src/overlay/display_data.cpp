// The display data both programs derive from a document (display_data.h).

#include "meshedit/overlay/display_data.h"

namespace meshedit {

void DisplayData::follow(const Mesh& mesh, const Change& change) {
    settle();
    if (change.mesh) {
        features_stale_ = true;
        field_stale_ = true;
        if (change.region != nullptr && !tree_stale_ && tree_revision_ == change.before) {
            tree_.update(mesh, faces_to_redraw(mesh, *change.region));
            tree_revision_ = change.after;
        } else {
            tree_stale_ = true;
        }
    }
    if (change.features) {
        features_stale_ = true;
    }
}

const OverlayBatch& DisplayData::features(const Mesh& mesh, bool edges, bool marks, bool seams,
                                          bool borders) {
    if (features_stale_ || edges != features_edges_ || marks != features_marks_ ||
        seams != features_seams_ || borders != features_borders_) {
        const OverlayStyle style;
        features_.clear();
        if (edges) {
            add_feature_edges(mesh, style, features_, seams, borders);
        }
        if (marks) {
            add_loop_phase_marks(mesh, style, features_);
        }
        features_stale_ = false;
        features_edges_ = edges;
        features_marks_ = marks;
        features_seams_ = seams;
        features_borders_ = borders;
    }
    return features_;
}

OverlayBatch DisplayData::overlay(const SceneContent& scene, bool edges, bool marks) {
    OverlayBatch batch;
    if (scene.mesh != nullptr && marks && scene.marks_near_selection &&
        is_live(*scene.mesh, scene.selected)) {
        // Filtered by the selection, which changes with every click: not cached.
        batch = features(*scene.mesh, edges, false, scene.uv_seams, scene.material_borders);
        add_loop_phase_marks(*scene.mesh, OverlayStyle(), batch,
                             vertices_near(*scene.mesh, scene.selected, 2));
    } else if (scene.mesh != nullptr && (edges || marks)) {
        batch = features(*scene.mesh, edges, marks, scene.uv_seams, scene.material_borders);
    }
    add_scene_marks(scene, OverlayStyle(), batch);
    return batch;
}

const FieldDisplay& DisplayData::field(const Mesh& mesh, const FieldRequest& request,
                                       bool* recomputed) {
    if (request.info == nullptr) {
        field_ = {};
        field_stale_ = true;
        return field_;
    }
    // A click or a display toggle leaves the values as they are: O(mesh) saved per event.
    if (!field_stale_ && field_.info == request.info && field_.source == request.source &&
        field_.clip == request.clip && field_.colormap == request.colormap) {
        return field_;
    }
    FieldOptions options;
    options.source = request.source;
    field_.info = request.info;
    field_.source = request.source;
    field_.clip = request.clip;
    field_.colormap = request.colormap;
    field_.values = compute_field(mesh, *request.info, options);
    field_.stats = field_stats(field_.values);
    field_.coloring = default_coloring(*request.info, field_.values, request.clip);
    if (request.colormap) {
        field_.coloring.map = *request.colormap;
    }
    field_stale_ = false;
    if (recomputed != nullptr) {
        *recomputed = true;
    }
    return field_;
}

void DisplayData::prebuild(const Mesh& mesh, std::uint64_t revision) {
    settle();
    if (!tree_stale_ && tree_revision_ == revision) {
        return;
    }
    building_.emplace();
    building_revision_ = revision;
    builder_ = std::jthread([this, &mesh] { building_->build(mesh); });
}

void DisplayData::settle() {
    if (!builder_.joinable()) {
        return;
    }
    builder_.join();
    tree_ = std::move(*building_);
    building_.reset();
    tree_stale_ = false;
    tree_revision_ = building_revision_;
}

const FaceBvh& DisplayData::picking_tree(const Mesh& mesh, std::uint64_t revision) {
    settle();
    if (tree_stale_ || tree_revision_ != revision) {
        tree_.build(mesh);
        tree_stale_ = false;
        tree_revision_ = revision;
    }
    return tree_;
}

}  // namespace meshedit
