#pragma once
/// \file
/// Named, typed property arrays (pmp-library's design). Connectivity and attributes of one
/// element kind live in one PropertyContainer, so adding, compacting or copying elements
/// treats every array the same way.

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
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

/// How a property follows an operation that makes an element from others (Mesh::carry(), the
/// attribute carry: docs/halfedge.md). With one source every rule but None copies it.
enum class Carry : std::uint8_t {
    Blend,     ///< the weighted sum of the sources (integers rounded, clamped): UVs, colours
    Heaviest,  ///< the value of the source with the largest weight: labels, ids, handles
    Any,       ///< the largest value among the sources: flags (a crease stays a crease)
    None,      ///< untouched (a new element keeps the default): data its algorithm writes
};

/// Values that can be blended: numbers, and vectors with `+` and `* double` (Vec3).
template <class T>
concept Blendable = std::is_arithmetic_v<T> || requires(T a, double w) {
    { a* w } -> std::convertible_to<T>;
    { a + a } -> std::convertible_to<T>;
};

/// The default rule of a type: numbers with a fraction and vectors blend; integers and
/// handles are labels and take the heaviest source.
template <class T>
constexpr Carry default_carry() {
    if constexpr (std::is_floating_point_v<T> || (Blendable<T> && !std::is_arithmetic_v<T>)) {
        return Carry::Blend;
    } else {
        return Carry::Heaviest;
    }
}

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
    /// A new array of the same name, type and default holding this one's values, which is
    /// left empty: a clone without copying, for a pass that rebuilds this array from the old
    /// values (the whole-mesh refinements' carry).
    virtual std::unique_ptr<BasePropertyArray> take_values() = 0;
    /// Exchanges the values with `other`, an array of the same type (take_values() undone).
    virtual void swap_values(BasePropertyArray& other) = 0;
    virtual const std::type_info& type() const = 0;
    virtual std::size_t bytes() const = 0;
    /// Bytes of one element, and its raw copy out of and back into the array (for recorded
    /// edits, mesh_change.h: every element type is trivially copyable).
    virtual std::size_t element_bytes() const = 0;
    virtual void save(std::size_t i, std::byte* out) const = 0;
    virtual void load(std::size_t i, const std::byte* in) = 0;
    /// Element i takes the value element `source[i]` had (every index, all at once).
    virtual void permute(const std::vector<std::uint32_t>& source) = 0;
    /// Sets element `to` from the `n` elements `from` with weights `weight` (summing to 1) by
    /// the array's carry rule; `n == 0` resets it to the default. `to` may be a source.
    virtual void derive(std::size_t to, const std::uint32_t* from, const double* weight,
                        std::size_t n) = 0;
    /// The same, reading the sources from `source`, an array of the same type (a rebuilt
    /// mesh's new array from its old one).
    virtual void derive_from(const BasePropertyArray& source, std::size_t to,
                             const std::uint32_t* from, const double* weight, std::size_t n) = 0;
    /// The numbers one element holds if the type blends (1 for a number, 3 for a Vec3),
    /// else 0; and channel `c` of every element as doubles, out and back in (integers
    /// rounded and clamped). An algorithm that maps positions linearly (subdivision) maps
    /// attributes through the same code this way.
    virtual std::size_t channels() const = 0;
    virtual void get_channel(std::size_t c, std::vector<double>& out) const = 0;
    virtual void set_channel(std::size_t c, const std::vector<double>& in) = 0;
    /// The elements' bytes when each is exactly its channels() doubles (double, Vec2, Vec3,
    /// Vec4), so that a pass can move every channel in one copy; else null.
    virtual const std::byte* channel_doubles() const = 0;
    virtual std::byte* channel_doubles() = 0;

    const std::string& name() const { return name_; }
    Carry carry() const { return carry_; }
    void set_carry(Carry rule) { carry_ = rule; }

protected:
    Carry carry_ = Carry::Heaviest;

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
        : BasePropertyArray(std::move(name)), default_(std::move(default_value)) {
        carry_ = default_carry<T>();
    }
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
    std::unique_ptr<BasePropertyArray> take_values() override {
        auto out = std::make_unique<PropertyArray<T>>(name(), default_);
        out->carry_ = carry_;
        out->data_.swap(data_);
        return out;
    }
    void swap_values(BasePropertyArray& other) override {
        MESHEDIT_ASSERT(other.type() == typeid(T));
        data_.swap(static_cast<PropertyArray<T>&>(other).data_);
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
    void permute(const std::vector<std::uint32_t>& source) override {
        memory::Array<T> old(data_);
        for (std::size_t i = 0; i < source.size(); ++i) {
            data_[i] = old[source[i]];
        }
    }
    void derive(std::size_t to, const std::uint32_t* from, const double* weight,
                std::size_t n) override {
        derive_from(*this, to, from, weight, n);
    }
    void derive_from(const BasePropertyArray& source, std::size_t to, const std::uint32_t* from,
                     const double* weight, std::size_t n) override {
        if (carry_ == Carry::None) {
            return;
        }
        const memory::Array<T>& src = static_cast<const PropertyArray<T>&>(source).data_;
        if (n <= 1) {
            data_[to] = n == 0 ? default_ : src[from[0]];
            return;
        }
        std::size_t heaviest = 0;
        for (std::size_t i = 1; i < n; ++i) {
            heaviest = weight[i] > weight[heaviest] ? i : heaviest;
        }
        T value = src[from[heaviest]];
        if constexpr (Blendable<T>) {
            if (carry_ == Carry::Blend) {
                value = blend(src, from, weight, n);
            }
        }
        if constexpr (std::totally_ordered<T>) {
            if (carry_ == Carry::Any) {
                for (std::size_t i = 0; i < n; ++i) {
                    value = std::max(value, src[from[i]]);
                }
            }
        }
        data_[to] = value;
    }
    std::size_t channels() const override {
        if constexpr (std::is_arithmetic_v<T>) {
            return 1;
        } else if constexpr (Blendable<T> && sizeof(T) % sizeof(double) == 0) {
            return sizeof(T) / sizeof(double);  // Vec3: three doubles
        } else {
            return 0;
        }
    }
    void get_channel(std::size_t c, std::vector<double>& out) const override {
        out.resize(data_.size());
        for (std::size_t i = 0; i < data_.size(); ++i) {
            if constexpr (std::is_arithmetic_v<T>) {
                out[i] = static_cast<double>(data_[i]);
            } else {
                std::memcpy(&out[i], reinterpret_cast<const std::byte*>(&data_[i]) + 8 * c, 8);
            }
        }
    }
    const std::byte* channel_doubles() const override {
        if constexpr (kChannelDoubles) {
            return reinterpret_cast<const std::byte*>(data_.data());
        }
        return nullptr;
    }
    std::byte* channel_doubles() override {
        if constexpr (kChannelDoubles) {
            return reinterpret_cast<std::byte*>(data_.data());
        }
        return nullptr;
    }
    void set_channel(std::size_t c, const std::vector<double>& in) override {
        for (std::size_t i = 0; i < data_.size() && i < in.size(); ++i) {
            if constexpr (std::is_integral_v<T>) {
                data_[i] = to_integer(in[i]);
            } else if constexpr (std::is_arithmetic_v<T>) {
                data_[i] = static_cast<T>(in[i]);
            } else {
                std::memcpy(reinterpret_cast<std::byte*>(&data_[i]) + 8 * c, &in[i], 8);
            }
        }
    }

    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    memory::Array<T>& vector() { return data_; }
    const memory::Array<T>& vector() const { return data_; }
    const T& default_value() const { return default_; }

private:
    static T to_integer(double x) {
        x = std::nearbyint(x);
        if (!(x > static_cast<double>(std::numeric_limits<T>::lowest()))) {
            return std::numeric_limits<T>::lowest();  // NaN too
        }
        if (!(x < static_cast<double>(std::numeric_limits<T>::max()))) {
            return std::numeric_limits<T>::max();
        }
        return static_cast<T>(x);
    }

    static T blend(const memory::Array<T>& src, const std::uint32_t* from, const double* weight,
                   std::size_t n) requires Blendable<T> {
        if constexpr (std::is_integral_v<T>) {
            double sum = 0.0;
            for (std::size_t i = 0; i < n; ++i) {
                sum += weight[i] * static_cast<double>(src[from[i]]);
            }
            return to_integer(sum);
        } else if constexpr (std::is_arithmetic_v<T>) {  // float: summed in double
            double sum = 0.0;
            for (std::size_t i = 0; i < n; ++i) {
                sum += weight[i] * static_cast<double>(src[from[i]]);
            }
            return static_cast<T>(sum);
        } else {
            T sum = src[from[0]] * weight[0];
            for (std::size_t i = 1; i < n; ++i) {
                sum = sum + src[from[i]] * weight[i];
            }
            return sum;
        }
    }

    // Whether each element is its channels as doubles (what get_channel() copies bytewise).
    static constexpr bool kChannelDoubles =
        std::is_same_v<T, double> ||
        (!std::is_arithmetic_v<T> && Blendable<T> && sizeof(T) % sizeof(double) == 0);

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
    /// Sets how the array named `name` follows operations. \return false if there is none.
    bool set_carry(std::string_view name, Carry rule) {
        BasePropertyArray* a = find(name);
        if (a != nullptr) {
            a->set_carry(rule);
        }
        return a != nullptr;
    }

    /// Permutes every array from index `first` on (BasePropertyArray::permute()).
    void permute(std::size_t first, const std::vector<std::uint32_t>& source) {
        for (std::size_t i = first; i < arrays_.size(); ++i) {
            arrays_[i]->permute(source);
        }
    }
    /// Derives element `to` of every array from index `first` on (Mesh::carry()).
    void derive(std::size_t first, std::size_t to, const std::uint32_t* from, const double* weight,
                std::size_t n) {
        for (std::size_t i = first; i < arrays_.size(); ++i) {
            arrays_[i]->derive(to, from, weight, n);
        }
    }

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
