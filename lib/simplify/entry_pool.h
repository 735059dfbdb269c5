// Where the collapse heap's entries come from.
#pragma once

#include <cstddef>
#include <memory_resource>

namespace cadlod {

// Heap entries are made and deleted by the million (every push and every re-queue): they
// come from a pool, which takes memory from malloc a chunk of entries at a time, and gives
// it all back when its last entry is deleted (a session's end). Each thread has a pool of
// its own; a session whose heap outlives one task (a half of collapse_halves.h, whose
// rounds may each run on another thread) brings its own and puts it in use (EntryPool::Use)
// wherever its entries are made or deleted.
class EntryPool
{
public:
    EntryPool() = default;
    EntryPool(const EntryPool&) = delete;
    EntryPool& operator=(const EntryPool&) = delete;

    // The pool entries come from on this thread while it lives.
    class Use
    {
    public:
        explicit Use(EntryPool& pool) : previous_(current()) { current() = &pool; }
        ~Use() { current() = previous_; }
        Use(const Use&) = delete;
        Use& operator=(const Use&) = delete;

    private:
        EntryPool* previous_;
    };

    static void* allocate(std::size_t size)
    {
        EntryPool& p = inUse();
        ++p.live_;
        return p.pool_.allocate(size);
    }
    static void deallocate(void* ptr, std::size_t size)
    {
        EntryPool& p = inUse();
        p.pool_.deallocate(ptr, size);
        if (--p.live_ == 0)
            p.pool_.release();
    }

private:
    static EntryPool*& current()
    {
        thread_local EntryPool* pool = nullptr;
        return pool;
    }
    static EntryPool& inUse()
    {
        thread_local EntryPool own;
        EntryPool* p = current();
        return p ? *p : own;
    }

    std::pmr::unsynchronized_pool_resource pool_;
    std::size_t live_ = 0;
};

}  // namespace cadlod
