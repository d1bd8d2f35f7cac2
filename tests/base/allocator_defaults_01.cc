// MemoryEstimate::restore_allocator_defaults(), run when perideal-base loads: a block of 64 MiB
// gets a mapping of its own (glibc's default for blocks of 128 KiB and more), which it does not
// while libsuperlu_dist's static mallopt(M_MMAP_MAX, 0) is in force; freeing it returns it, and
// calling the function again is accepted. See doc/benchmarks/performance/README.md, "Memory".

#include <perideal/base/memory_estimate.h>

#include "../tests.h"

#include <cstdlib>

#include <malloc.h>

using namespace dealii;
using namespace perideal;

int
main()
{
  initlog();
  const std::size_t mapped_before = mallinfo2().hblkhd;
  void             *block         = std::malloc(std::size_t(64) << 20);
  AssertThrow(block != nullptr, ExcMessage("malloc of 64 MiB failed"));
  const std::size_t mapped_with = mallinfo2().hblkhd;
  std::free(block);
  const std::size_t mapped_after = mallinfo2().hblkhd;
  deallog << "64 MiB block in a mapping of its own: "
          << (mapped_with >= mapped_before + (std::size_t(64) << 20) ? "yes" : "no") << std::endl;
  deallog << "returned when freed: " << (mapped_after == mapped_before ? "yes" : "no") << std::endl;
  deallog << "restore_allocator_defaults() again: "
          << (MemoryEstimate::restore_allocator_defaults() ? "accepted" : "refused") << std::endl;
}
