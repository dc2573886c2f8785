// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#include <dpana/linear_algebra/blas_threads.h>

#include <dlfcn.h>

namespace dpana
{
  namespace linear_algebra
  {
    namespace
    {
      using SetThreads = void (*)(int);
      using GetThreads = int (*)();

      // OpenBLAS' calls in the BLAS this process has loaded; null where it
      // has none.
      SetThreads
      set_threads()
      {
        return reinterpret_cast<SetThreads>(
          dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
      }

      GetThreads
      get_threads()
      {
        return reinterpret_cast<GetThreads>(
          dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
      }
    } // namespace



    SingleThreadedBlas::SingleThreadedBlas()
    {
      const SetThreads set = set_threads();
      const GetThreads get = get_threads();
      if (set == nullptr || get == nullptr)
        return;
      previous = get();
      set(1);
    }



    SingleThreadedBlas::~SingleThreadedBlas()
    {
      if (previous > 0)
        set_threads()(previous);
    }



    void
    serial_openmp_regions()
    {
      using SetLevels              = void (*)(int);
      static const auto set_levels = reinterpret_cast<SetLevels>(
        dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
      if (set_levels != nullptr)
        set_levels(0);
    }
  } // namespace linear_algebra
} // namespace dpana
