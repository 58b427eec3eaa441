// The right-hand side allocates nothing (issue 2): operator new is counted around accelerations().
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "inerta/io/model_file.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/mbs/dynamics.hpp"

static std::atomic<long> g_allocations{0};

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace inerta;

TEST(Allocation, RightHandSideAllocatesNothing) {
  for (const char* file : {"/models/twobar.yaml", "/models/onedof.yaml", "/models/twobar3d.yaml",
                           "/models/spherical_inerter.yaml"}) {
    mbs::Model model = io::load_model(std::string(INERTA_SOURCE_DIR) + file);
    mbs::State x = mbs::assemble(model, 0.0);
    x.qd.setConstant(0.2);
    mbs::Workspace ws(model);
    mbs::accelerations(model, 0.0, x, ws);  // warm-up
    long before = g_allocations.load();
    for (int k = 0; k < 100; ++k) mbs::accelerations(model, 0.01 * k, x, ws);
    EXPECT_EQ(g_allocations.load() - before, 0) << file;
    // The counter works: a Workspace allocates.
    before = g_allocations.load();
    { mbs::Workspace other(model); }
    EXPECT_GT(g_allocations.load() - before, 0);
  }
}
