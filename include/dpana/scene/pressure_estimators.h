// ---------------------------------------------------------------------------
// dpana: dual condensed frictional contact between linear elastic bodies.
// ---------------------------------------------------------------------------
#ifndef dpana_scene_pressure_estimators_h
#define dpana_scene_pressure_estimators_h

#include <array>
#include <vector>

namespace dpana
{
  namespace scene
  {
    /**
     * One contact element of a 2D contact surface as the estimators see it:
     * its extent [s_min, s_max] along the surface and its constant contact
     * pressure p = -N (MPa).
     */
    struct PressureElement
    {
      double s_min, s_max, pressure;
    };

    /**
     * Estimates of the contact zone finer than one contact element, from a
     * piecewise constant pressure p(s) (see doc/contact.md, "Estimators of
     * the half width"). Positions are measured along s from the candidate
     * centre s0. A surface that lies on one side of s0 and whose body is
     * held across s0 there (a symmetry line) is the half model of a body
     * symmetric about s0: its pressure is mirrored about s0, and the
     * resultant is that of the modelled half.
     */
    struct PressureEstimates
    {
      // False in 3D, and in 2D when no element is pressed (the fields down
      // to fit_centre, but for the resultant, which 3D runs set with the
      // point centroid below).
      bool available = false;
      // The surface is a half model, mirrored about s0.
      bool mirrored = false;
      // Resultant R = int p ds of the modelled surface (N/mm) and the
      // pressure centroid c = int s p ds / R (mm from s0; 0 when mirrored).
      double resultant = 0, centroid = 0;
      // The moment estimate a_m = 2 sqrt(int (s - c)^2 p ds / R).
      double moment_half_width = 0;
      // The elliptic fit p = p0 sqrt(1 - (s - c_f)^2 / a_f^2): whether the
      // fit exists, a_f, p0 and c_f (mm from s0).
      bool   fit_available    = false;
      double fit_half_width   = 0;
      double fit_max_pressure = 0;
      double fit_centre       = 0;
      // 3D: the centroid (x, y, z) of the pressure p = max(-N, 0) of the
      // modelled surface (mm; a quarter model's lies in its quarter), each
      // element's pressure acting at its centroid, and whether it was
      // computed (an element in contact); resultant above holds the
      // pressure's resultant (N).
      bool                  point_centroid_available = false;
      std::array<double, 3> point_centroid           = {{0, 0, 0}};
      // 3D Hertz scenes: the approach delta of the bodies measured from
      // their displacements (References::measure_approach(), mm), and
      // whether it was measured.
      bool   approach_measured = false;
      double approach          = 0;
    };

    /**
     * The estimators of PressureEstimates for the elements @p elements of a
     * 2D contact surface, positions measured from @p s0:
     *
     * - the resultant R and the centroid c of the pressure, integrated
     *   exactly over the elements;
     * - the moment estimate a_m = 2 sqrt(int (s - c)^2 p ds / R), the
     *   integrals exact for the piecewise constant pressure. For the
     *   elliptic law p = p0 sqrt(1 - (s - c)^2 / a^2) of Hertz,
     *   int (s - c)^2 p ds = pi p0 a^3 / 8 and R = pi p0 a / 2, so a_m = a
     *   exactly; it assumes only that law, not where the zone ends;
     * - the elliptic fit: the least squares fit, weighted by the element
     *   lengths, of p^2 = A + B s + C s^2 (the elliptic law squared,
     *   p0^2 (1 - (s - c_f)^2 / a_f^2)) to the squared pressures of the
     *   pressed elements (p above 1e-9 of the largest: the separated ones
     *   carry round-off), each taken at its centroid; then c_f = -B / 2C,
     *   p0^2 = A - B^2 / 4C and a_f^2 = -p0^2 / C. With a mirrored half
     *   model B = 0. It needs 3 pressed elements (2 mirrored), C < 0, and
     *   a_f less than twice the extent of the pressed elements from s0
     *   (a flatter profile is not elliptic).
     */
    PressureEstimates
    estimate_pressure_profile(const std::vector<PressureElement> &elements,
                              const double                        s0,
                              const bool symmetric_about_s0 = true);
  } // namespace scene
} // namespace dpana

#endif
