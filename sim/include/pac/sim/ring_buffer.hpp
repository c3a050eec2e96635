// A first-in first-out queue in slots that wrap around, for what the simulator keeps per cycle (the exchange
// log, the images in flight on a bus link): once there are as many slots as the queue has ever held, appending
// and dropping the oldest allocate nothing. The slots come in chunks of Chunk that never move, so growing
// copies no element (a queue that grows long, as the exchange log, takes larger chunks: fewer allocations).
// With a limit, appending to a full queue drops the oldest. Read like a std::deque: size(), [0] the oldest,
// back() the newest, iterators oldest first.
#pragma once

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory>
#include <vector>

namespace pac::sim {

template <class T, std::size_t Chunk = 16>
class RingBuffer {
public:
    class const_iterator {
    public:
        using iterator_category = std::random_access_iterator_tag;
        using value_type = T;
        using difference_type = std::ptrdiff_t;
        using pointer = const T*;
        using reference = const T&;

        const_iterator() = default;
        reference operator*() const { return (*ring_)[index_]; }
        pointer operator->() const { return &(*ring_)[index_]; }
        reference operator[](difference_type n) const { return (*ring_)[Offset(n)]; }
        const_iterator& operator++() { ++index_; return *this; }
        const_iterator operator++(int) { const_iterator old = *this; ++index_; return old; }
        const_iterator& operator--() { --index_; return *this; }
        const_iterator operator--(int) { const_iterator old = *this; --index_; return old; }
        const_iterator& operator+=(difference_type n) { index_ = Offset(n); return *this; }
        const_iterator& operator-=(difference_type n) { index_ = Offset(-n); return *this; }
        friend const_iterator operator+(const_iterator it, difference_type n) { return it += n; }
        friend const_iterator operator+(difference_type n, const_iterator it) { return it += n; }
        friend const_iterator operator-(const_iterator it, difference_type n) { return it -= n; }
        friend difference_type operator-(const const_iterator& a, const const_iterator& b) {
            return static_cast<difference_type>(a.index_) - static_cast<difference_type>(b.index_);
        }
        friend bool operator==(const const_iterator& a, const const_iterator& b) { return a.index_ == b.index_; }
        friend bool operator!=(const const_iterator& a, const const_iterator& b) { return a.index_ != b.index_; }
        friend bool operator<(const const_iterator& a, const const_iterator& b) { return a.index_ < b.index_; }
        friend bool operator>(const const_iterator& a, const const_iterator& b) { return a.index_ > b.index_; }
        friend bool operator<=(const const_iterator& a, const const_iterator& b) { return a.index_ <= b.index_; }
        friend bool operator>=(const const_iterator& a, const const_iterator& b) { return a.index_ >= b.index_; }

    private:
        friend class RingBuffer;
        const_iterator(const RingBuffer* ring, std::size_t index) : ring_(ring), index_(index) {}
        std::size_t Offset(difference_type n) const {
            return static_cast<std::size_t>(static_cast<difference_type>(index_) + n);
        }
        const RingBuffer* ring_ = nullptr;
        std::size_t index_ = 0;  // 0: the oldest
    };
    using const_reverse_iterator = std::reverse_iterator<const_iterator>;
    using value_type = T;
    using size_type = std::size_t;

    // limit: the most elements held (at least 1); appending beyond it drops the oldest.
    explicit RingBuffer(std::size_t limit = std::numeric_limits<std::size_t>::max()) : limit_(limit < 1 ? 1 : limit) {}

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    // i-th oldest (0..size()-1; no check, as std::deque's operator[]).
    const T& operator[](std::size_t i) const { return At(Slot(i)); }
    const T& front() const { return At(head_); }
    const T& back() const { return At(Slot(size_ - 1)); }
    const_iterator begin() const { return const_iterator(this, 0); }
    const_iterator end() const { return const_iterator(this, size_); }
    const_reverse_iterator rbegin() const { return const_reverse_iterator(end()); }
    const_reverse_iterator rend() const { return const_reverse_iterator(begin()); }

    // The slot of a new newest element, to be assigned in full: it holds whatever an element dropped earlier
    // left there.
    T& push_back() {
        if (size_ == limit_) {  // full: the oldest slot becomes the newest
            T& slot = At(head_);
            head_ = Slot(1);
            return slot;
        }
        if (size_ == slots_) Grow();
        ++size_;
        return At(Slot(size_ - 1));
    }
    void push_back(const T& value) { push_back() = value; }
    // Drops the oldest (the queue must not be empty).
    void pop_front() {
        head_ = Slot(1);
        --size_;
    }
    void clear() {
        head_ = 0;
        size_ = 0;
    }

private:
    static constexpr std::size_t kChunk = Chunk;
    static_assert(kChunk > 0, "a chunk holds at least one slot");

    T& At(std::size_t slot) const { return chunks_[slot / kChunk][slot % kChunk]; }
    std::size_t Slot(std::size_t i) const {
        const std::size_t k = head_ + i;
        return k >= slots_ ? k - slots_ : k;
    }
    // One chunk more (its slots up to the limit), behind the newest element.
    void Grow() {
        if (head_ != 0) {  // wrapped: the oldest back to slot 0, so that the new slots follow the newest
            std::vector<T> order(size_);
            for (std::size_t i = 0; i < size_; ++i) order[i] = std::move(At(Slot(i)));
            for (std::size_t i = 0; i < size_; ++i) At(i) = std::move(order[i]);
            head_ = 0;
        }
        chunks_.push_back(std::make_unique<T[]>(kChunk));
        slots_ = std::min(chunks_.size() * kChunk, limit_);
    }

    std::vector<std::unique_ptr<T[]>> chunks_;
    std::size_t slots_ = 0;  // usable slots: the chunks', at most limit_
    std::size_t head_ = 0;   // the oldest element's slot
    std::size_t size_ = 0;
    std::size_t limit_;
};

}  // namespace pac::sim
