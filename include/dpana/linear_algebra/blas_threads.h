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
  } // namespace linear_algebra
} // namespace dpana

#endif
