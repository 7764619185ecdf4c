#pragma once
// The allocator behind a curve's per-point arrays. Small arrays come from
// std::allocator. Large ones (at least large_array_bytes) are, on Linux,
// mappings of their own, aligned to 2 MiB and advised for transparent huge
// pages, unmapped when freed (issue 30: taken from malloc with 2 MiB
// alignment, freed blocks were not reused for the next aligned request, so
// a program rebuilding a large curve grew its heap by the curve's size
// each time, and a construction's cost depended on the heap's history). A
// 10^6-point
// curve then takes ~900 page faults for its ~68 MB instead of
// ~17000 (first touch of fresh memory, not arithmetic, was most of its
// construction time: 49 ms against 23 ms on the bench machine, see
// BENCHMARKS.md). Define CRSPLINE_NO_HUGE_PAGES to allocate everything
// plainly, e.g. where a stall for memory compaction matters more than
// throughput.
// Arrays of trivial values are left uninitialized by resize(): the curve's
// build writes every element once.
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>
#include <new>
#include <type_traits>
#include <utility>

#if defined(__linux__) && !defined(__EMSCRIPTEN__) && !defined(CRSPLINE_NO_HUGE_PAGES)
#include <sys/mman.h>
#include <cstdint>
#define CRSPLINE_HUGE_PAGES 1
#endif

namespace crspline::detail {

inline constexpr std::size_t huge_page_bytes = std::size_t(2) << 20;
inline constexpr std::size_t large_array_bytes = std::size_t(4) << 20;

/// Advice that the untouched memory [p, p + bytes) of a large buffer (at
/// least large_array_bytes, e.g. a std::vector's reserved capacity) be
/// backed by transparent huge pages when first touched: its 2 MiB-aligned
/// inner part. Nothing where huge pages are off (CRSPLINE_NO_HUGE_PAGES,
/// not Linux); advice only.
inline void advise_huge_pages(const void* p, std::size_t bytes) noexcept {
#ifdef CRSPLINE_HUGE_PAGES
    if (bytes < large_array_bytes) return;
    const std::uintptr_t r = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t a = (r + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
    const std::uintptr_t e = (r + bytes) / huge_page_bytes * huge_page_bytes;
    if (e > a) ::madvise(reinterpret_cast<void*>(a), e - a, MADV_HUGEPAGE);
#else
    (void)p, (void)bytes;
#endif
}

template <class T>
struct storage_allocator {
    using value_type = T;
    storage_allocator() noexcept = default;
    template <class U>
    storage_allocator(const storage_allocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
#ifdef CRSPLINE_HUGE_PAGES
        const std::size_t bytes = n * sizeof(T);
        if (bytes >= large_array_bytes) {
            // Map one huge page more than needed and unmap what lies outside
            // the aligned range.
            const std::size_t len = mapped_bytes(n);
            void* raw = ::mmap(nullptr, len + huge_page_bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                               -1, 0);
            if (raw == MAP_FAILED) throw std::bad_alloc();
            const std::uintptr_t r = reinterpret_cast<std::uintptr_t>(raw);
            const std::uintptr_t a = (r + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
            if (a > r) ::munmap(raw, a - r);
            if (r + huge_page_bytes > a) ::munmap(reinterpret_cast<void*>(a + len), r + huge_page_bytes - a);
            // Advice only: where the kernel has no huge page to give, or THP
            // is off, the range stays in 4 KiB pages.
            ::madvise(reinterpret_cast<void*>(a), len, MADV_HUGEPAGE);
            return reinterpret_cast<T*>(a);
        }
#endif
        return std::allocator<T>{}.allocate(n);
    }
    void deallocate(T* p, std::size_t n) noexcept {
#ifdef CRSPLINE_HUGE_PAGES
        if (n * sizeof(T) >= large_array_bytes) {
            ::munmap(static_cast<void*>(p), mapped_bytes(n));
            return;
        }
#endif
        std::allocator<T>{}.deallocate(p, n);
    }
    // resize() leaves a double, an index or a point uninitialized for the
    // build to write once instead of zeroing it first (issue 30: zeroing
    // the tangents was 8% of a construction). A point (vec) is an aggregate,
    // trivially copyable and destructible: an implicit-lifetime type, which
    // allocate() already created (C++20 [intro.object]), so skipping its
    // member initializers here is sound; the build writes every element
    // before anything reads it (tests/unit: the curves compare bit for bit).
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        if constexpr (!(std::is_aggregate_v<U> && std::is_trivially_copyable_v<U> &&
                        std::is_trivially_destructible_v<U>))
            ::new (static_cast<void*>(p)) U;
        else
            (void)p;
    }
    template <class U, class... A>
    void construct(U* p, A&&... a) {
        ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
    }
    template <class U>
    bool operator==(const storage_allocator<U>&) const noexcept { return true; }

private:
    // A large array's mapping: its bytes rounded up to whole huge pages.
    static std::size_t mapped_bytes(std::size_t n) noexcept {
        return (n * sizeof(T) + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
    }
};

template <class T>
using storage = std::vector<T, storage_allocator<T>>;

}  // namespace crspline::detail
