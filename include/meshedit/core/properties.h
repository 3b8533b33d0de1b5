#pragma once
/// \file
/// Named, typed property arrays (pmp-library's design). Connectivity and attributes of one
/// element kind live in one PropertyContainer, so adding, compacting or copying elements
/// treats every array the same way.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

#include "meshedit/core/pod_array.h"

namespace meshedit {

/// Type-erased interface of one property array.
class BasePropertyArray {
public:
    explicit BasePropertyArray(std::string name) : name_(std::move(name)) {}
    virtual ~BasePropertyArray() = default;
    BasePropertyArray(const BasePropertyArray&) = default;
    BasePropertyArray& operator=(const BasePropertyArray&) = delete;

    virtual void reserve(std::size_t n) = 0;
    virtual void resize(std::size_t n) = 0;
    virtual void push_back() = 0;
    /// Appends `k` default elements.
    virtual void push_back_n(std::size_t k) = 0;
    virtual void shrink_to_fit() = 0;
    /// Keeps the elements `kept[0], kept[1], …` (strictly increasing) as `0, 1, …`.
    virtual void compact(const std::vector<std::uint32_t>& kept) = 0;
    virtual std::unique_ptr<BasePropertyArray> clone() const = 0;
    virtual const std::type_info& type() const = 0;
    virtual std::size_t bytes() const = 0;
    /// Bytes of one element, and its raw copy out of and back into the array (for recorded
    /// edits, mesh_change.h: every element type is trivially copyable).
    virtual std::size_t element_bytes() const = 0;
    virtual void save(std::size_t i, std::byte* out) const = 0;
    virtual void load(std::size_t i, const std::byte* in) = 0;

    const std::string& name() const { return name_; }

private:
    std::string name_;
};

/// A property array of element type `T`. `bool` is not allowed (std::vector<bool> hands out
/// proxies, not references); use `std::uint8_t` for flags.
template <class T>
class PropertyArray final : public BasePropertyArray {
    static_assert(!std::is_same_v<T, bool>, "use std::uint8_t for flag properties");
    static_assert(std::is_trivially_copyable_v<T>, "properties hold trivially copyable types");

public:
    PropertyArray(std::string name, T default_value)
        : BasePropertyArray(std::move(name)), default_(std::move(default_value)) {}
    void reserve(std::size_t n) override { data_.reserve(n); }
    void resize(std::size_t n) override { data_.resize(n, default_); }
    void push_back() override { data_.push_back(default_); }
    void push_back_n(std::size_t k) override { memory::append(data_, k, default_); }
    void shrink_to_fit() override { data_.shrink_to_fit(); }
    void compact(const std::vector<std::uint32_t>& kept) override {
        for (std::size_t i = 0; i < kept.size(); ++i) {
            if (kept[i] != i) {
                data_[i] = std::move(data_[kept[i]]);
            }
        }
        data_.resize(kept.size());
    }
    std::unique_ptr<BasePropertyArray> clone() const override {
        return std::make_unique<PropertyArray<T>>(*this);
    }
    const std::type_info& type() const override { return typeid(T); }
    std::size_t bytes() const override { return data_.capacity() * sizeof(T); }
    std::size_t element_bytes() const override { return sizeof(T); }
    void save(std::size_t i, std::byte* out) const override {
        std::memcpy(out, &data_[i], sizeof(T));
    }
    void load(std::size_t i, const std::byte* in) override {
        std::memcpy(&data_[i], in, sizeof(T));
    }

    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    memory::Array<T>& vector() { return data_; }
    const memory::Array<T>& vector() const { return data_; }
    const T& default_value() const { return default_; }

private:
    memory::Array<T> data_;  // big arrays in huge pages (memory.h)
    T default_;
};

/// A typed view of one property array, indexed by the handle type `H` (Vertex, Edge, …).
/// It is a non-owning pointer: it stays usable while the property exists in its mesh.
template <class H, class T>
class Property {
public:
    Property() = default;
    explicit Property(PropertyArray<T>* array) : array_(array) {}

    explicit operator bool() const { return array_ != nullptr; }
    T& operator[](H h) { return (*array_)[h.idx()]; }
    const T& operator[](H h) const { return (*array_)[h.idx()]; }
    memory::Array<T>& vector() { return array_->vector(); }
    const memory::Array<T>& vector() const { return array_->vector(); }
    const std::string& name() const { return array_->name(); }
    PropertyArray<T>* array() const { return array_; }

private:
    PropertyArray<T>* array_ = nullptr;
};

/// All property arrays of one element kind; every array always has `size()` entries.
class PropertyContainer {
public:
    PropertyContainer() = default;
    PropertyContainer(const PropertyContainer& other) { *this = other; }
    PropertyContainer(PropertyContainer&&) noexcept = default;
    PropertyContainer& operator=(PropertyContainer&&) noexcept = default;
    PropertyContainer& operator=(const PropertyContainer& other) {
        if (this != &other) {
            arrays_.clear();
            arrays_.reserve(other.arrays_.size());
            for (const auto& a : other.arrays_) {
                arrays_.push_back(a->clone());
            }
            size_ = other.size_;
        }
        return *this;
    }

    std::size_t size() const { return size_; }
    std::size_t n_properties() const { return arrays_.size(); }

    /// Adds an array named `name`. \throws std::logic_error if the name is taken.
    template <class T>
    PropertyArray<T>* add(std::string name, T default_value = T()) {
        if (find(name) != nullptr) {
            throw std::logic_error("property '" + name + "' already exists");
        }
        auto array = std::make_unique<PropertyArray<T>>(std::move(name), std::move(default_value));
        array->resize(size_);
        auto* raw = array.get();
        arrays_.push_back(std::move(array));
        return raw;
    }

    /// \return the array named `name` if it exists with element type `T`, else nullptr.
    template <class T>
    PropertyArray<T>* get(std::string_view name) const {
        BasePropertyArray* a = find(name);
        return (a != nullptr && a->type() == typeid(T)) ? static_cast<PropertyArray<T>*>(a)
                                                        : nullptr;
    }

    /// \return the array named `name`, adding it if missing.
    /// \throws std::logic_error if it exists with another element type.
    template <class T>
    PropertyArray<T>* get_or_add(std::string_view name, T default_value = T()) {
        if (BasePropertyArray* a = find(name)) {
            if (a->type() != typeid(T)) {
                throw std::logic_error("property '" + std::string(name) + "' has another type");
            }
            return static_cast<PropertyArray<T>*>(a);
        }
        return add<T>(std::string(name), std::move(default_value));
    }

    bool exists(std::string_view name) const { return find(name) != nullptr; }

    /// The arrays in the order they were added (connectivity first).
    BasePropertyArray& array(std::size_t i) { return *arrays_[i]; }
    const BasePropertyArray& array(std::size_t i) const { return *arrays_[i]; }
    /// Adds a whole array (of size() elements), e.g. one an undone edit had added.
    void add_array(std::unique_ptr<BasePropertyArray> array) {
        arrays_.push_back(std::move(array));
    }
    /// Removes every array after the first `n`.
    void truncate_arrays(std::size_t n) { arrays_.resize(std::min(n, arrays_.size())); }

    /// Removes the array (no-op for nullptr or an array of another container).
    void remove(const BasePropertyArray* array) {
        auto it = std::find_if(arrays_.begin(), arrays_.end(),
                               [&](const auto& a) { return a.get() == array; });
        if (it != arrays_.end()) {
            arrays_.erase(it);
        }
    }

    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto& a : arrays_) {
            out.push_back(a->name());
        }
        return out;
    }

    void reserve(std::size_t n) {
        for (auto& a : arrays_) {
            a->reserve(n);
        }
    }
    void resize(std::size_t n) {
        for (auto& a : arrays_) {
            a->resize(n);
        }
        size_ = n;
    }
    void push_back() {
        for (auto& a : arrays_) {
            a->push_back();
        }
        ++size_;
    }
    /// Appends `k` default elements to every array: one call per array, not one per element.
    void push_back_n(std::size_t k) {
        for (auto& a : arrays_) {
            a->push_back_n(k);
        }
        size_ += k;
    }
    void shrink_to_fit() {
        for (auto& a : arrays_) {
            a->shrink_to_fit();
        }
    }
    void compact(const std::vector<std::uint32_t>& kept) {
        for (auto& a : arrays_) {
            a->compact(kept);
        }
        size_ = kept.size();
    }
    std::size_t bytes() const {
        std::size_t total = 0;
        for (const auto& a : arrays_) {
            total += a->bytes();
        }
        return total;
    }

private:
    BasePropertyArray* find(std::string_view name) const {
        for (const auto& a : arrays_) {
            if (a->name() == name) {
                return a.get();
            }
        }
        return nullptr;
    }

    std::vector<std::unique_ptr<BasePropertyArray>> arrays_;
    std::size_t size_ = 0;
};

}  // namespace meshedit
