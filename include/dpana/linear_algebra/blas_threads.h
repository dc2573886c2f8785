// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_linear_algebra_blas_threads_h
#define dpana_linear_algebra_blas_threads_h

namespace dpana
{
  namespace linear_algebra
  {
    /**
     * While an object of this class lives, the system BLAS runs each call
     * on the thread that makes it; its destructor gives the BLAS back the
     * number of threads it had before.
     *
     * For work that runs several BLAS callers at once, one per core: the
     * bodies of a scene factorised and condensed concurrently
     * (scene::Scene::condense()). With its own threads the BLAS would put
     * two or more threads on each core, and OpenBLAS' idle threads wait by
     * spinning, which takes the cores from the callers: two bodies of
     * 35 000 and 39 000 dofs factorised at once took 1.0-1.1 s with
     * OpenBLAS on two threads and 0.46-0.48 s on one, against 0.77-1.05 s
     * one body after the other.
     *
     * The number is set through OpenBLAS' openblas_set_num_threads(), looked
     * up at run time; a BLAS without it (the reference BLAS runs on one
     * thread anyway) is left as it is.
     */
    class SingleThreadedBlas
    {
    public:
      SingleThreadedBlas();
      ~SingleThreadedBlas();

      SingleThreadedBlas(const SingleThreadedBlas &) = delete;
      SingleThreadedBlas &
      operator=(const SingleThreadedBlas &) = delete;

    private:
      /// OpenBLAS' number of threads before; 0: not OpenBLAS.
      int previous = 0;
    };



    /**
     * Makes the OpenMP parallel regions that the calling thread reaches
     * run on that thread alone (its OpenMP max-active-levels set to 0,
     * through omp_set_max_active_levels() looked up at run time; a process
     * without OpenMP is left as it is). The setting belongs to the thread:
     * call it on each thread that factorises.
     *
     * Of dpana's libraries only CHOLMOD has such regions: short loops of
     * its supernodal factorisation (clearing and filling each supernode)
     * that it was compiled to run on 4 threads, whatever the machine and
     * whatever OMP_NUM_THREADS says. The factorisation's parallel work is
     * the BLAS'; on top of it the 4 OpenMP threads of each caller take the
     * cores from the BLAS and, on a small matrix, cost more to start than
     * the loops they run. On the 2-core machine of the benchmarks the
     * factorisation of the graded disc (95 642 dofs) took 1.22 s (median of
     * 6) with the loops on one thread against 1.45 s with 4, and that of
     * the two blocks of 50 and 162 dofs 4-5 ms against 10 ms.
     */
    void
    serial_openmp_regions();
  } // namespace linear_algebra
} // namespace dpana

#endif
