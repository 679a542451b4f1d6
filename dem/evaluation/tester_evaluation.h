#pragma once
// Evaluations of the wear tester per revolution (docs/theory.md section 7): wear per face set
// (total, column, convex element), normal force on the sample, bottom-layer speeds, the
// coefficients of variation that judge steady state, and least-squares fits of wear volume
// vs revolutions.
#include "dem/engine/clumps.h"
#include "dem/engine/particles.h"
#include "meshes/geometry_parameters.h"
#include "meshes/sample_frame.h"
#include "meshes/surface_mesh.h"

#include <map>
#include <string>
#include <vector>

namespace wear::dem {

/// Mean and standard deviation of samples.
struct Statistic {
  double mean = 0, std = 0;
  double cv() const { return mean != 0 ? std / std::abs(mean) : 0; } ///< [-]
};
Statistic statistic(const std::vector<double>& samples);

/// Least-squares fits through the origin, y = a x and y = b x^2 + c x, with R^2 (about the
/// mean of y).
struct WearFits {
  double a = 0, r2_linear = 0;
  double b = 0, c = 0, r2_quadratic = 0;
  int n_points = 0;
};
WearFits fit_wear(const std::vector<double>& x, const std::vector<double>& y);

struct RevolutionRecord {
  int revolution = 0;                   ///< 1-based
  double time = 0;                      ///< [s] simulated, at the end of the revolution
  double wear_volume = 0;               ///< [m^3] removed from the wear face in this revolution
  double wear_volume_other = 0;         ///< [m^3] removed from sides and bottom (not receding)
  double wear_volume_cumulative = 0;    ///< [m^3] wear face, all revolutions so far
  double contact_total_wear_volume = 0; ///< [m^3] all faces, from per-contact sums
  std::vector<double> column_wear;      ///< [m^3] per column (base strip + elements)
  std::map<int, double> element_wear;   ///< [m^3] per convex element label
  double mean_element_increment = 0;    ///< [m^3] dv(j): element wear / n elements
  Statistic normal_force;               ///< [N] sum of F_n on the wear face
  std::vector<Statistic> column_normal_force; ///< [N] per column
  Statistic bottom_speed;      ///< [m/s] particles within a diameter of the face, all samples
  Statistic bottom_spin;       ///< [rad/s] the same particles' angular speed
  double bottom_count = 0;     ///< [-] mean number of bottom-layer particles
  Statistic speed_over_sample; ///< [m/s] all particles above the footprint
  Statistic bed_height;        ///< [m] free surface above the wear face
  Statistic wear_rate;         ///< [m^3/s] of the wear face
  bool steady = false;         ///< the three coefficients of variation below the threshold
  int steady_revolution = 0;   ///< first revolution judged steady (0: not yet)
  WearFits fits;               ///< cumulative wear vs revolutions from the steady revolution
  int fits_from = 0;           ///< revolution the fit starts at (0: from the start)
  // Reference deformation (zero when off).
  double swept_volume = 0;         ///< [m^3] cumulative sum |dp_c| A
  double applied_volume = 0;       ///< [m^3] cumulative removed volume applied to nodes
  double enclosed_volume_loss = 0; ///< [m^3] cumulative
  double min_angle_deg = 0;        ///< [deg] smallest triangle angle of the worn surface
  std::string distortion;          ///< first distortion, empty if none
  double wall_seconds = 0;         ///< [s] wall-clock time of the revolution
  double particle_steps_per_second = 0;
};

/// The samples taken so far in an open revolution (kept by a checkpoint inside a revolution).
struct RevolutionSamples {
  double start_time = 0, last_time = 0;           ///< [s] of the revolution, of the last sample
  std::vector<double> last_removed, last_impulse; ///< [m^3], [N s] per face at the last sample
  std::vector<double> force;                      ///< [N] normal force per sample
  std::vector<double> speed;                      ///< [m/s] mean speed over the sample
  std::vector<double> height;                     ///< [m] bed height per sample
  std::vector<double> rate;                       ///< [m^3/s] wear rate per sample
  std::vector<double> bottom_count;               ///< [-] bottom-layer particles per sample
  std::vector<std::vector<double>> column_force;  ///< [N] per column, per sample
  double bottom_n = 0;                            ///< [-] bottom particles over all samples
  double bottom_v = 0, bottom_v2 = 0;             ///< [m/s], [m^2/s^2] sums of their speeds
  double bottom_w = 0, bottom_w2 = 0;             ///< [rad/s], [rad^2/s^2] sums of their spins
};

/// The grains over the sample as the evaluation reads them: each sphere, and each clump as
/// one body, in the sample's frame. A body's centre is its centre of mass, its speed that
/// centre's, its spin the body's angular speed |omega| (space frame, which is the tester's and
/// the sample's: the sample stands still), its gap the least over its members of the
/// member's lowest point above the wear surface under it, its top the highest member point.
struct BedGrains {
  std::vector<Vec3> centre;  ///< [m] sample frame
  std::vector<double> speed; ///< [m/s]
  std::vector<double> spin;  ///< [rad/s]
  std::vector<double> gap;   ///< [m] above the wear surface
  std::vector<double> top;   ///< [m] sample frame z of the highest point
  std::size_t size() const { return speed.size(); }
  void add(const Vec3& x, double v, double w, double g, double t);
  /// Seven values per grain, in order, for a gather over ranks; and back (appended).
  std::vector<double> packed() const;
  void append_packed(const std::vector<double>& values);
};

class TesterEvaluation {
public:
  /// `sample`: the sample surface in its own frame (face order as in the DEM wall).
  TesterEvaluation(const meshes::SurfaceMesh& sample, const meshes::SampleGeometry& geometry,
                   const meshes::SamplePlacement& placement, double layer_diameter,
                   double steady_threshold, int steady_revolutions);

  /// Takes a new sample surface (sample frame; e.g. remeshed): per-face columns and labels
  /// are derived anew, the revolution history is kept.
  void set_surface(const meshes::SurfaceMesh& sample);

  int n_columns() const { return n_columns_; }
  const std::vector<int>& element_labels() const { return element_labels_; }
  /// Column (1-based) of each face, 0 for sides and bottom.
  const std::vector<int>& face_column() const { return face_column_; }

  void begin_revolution(double time);
  /// One sample during the revolution, of the grains over the sample (grains(); over ranks,
  /// every rank's in rank order); `removed` and `normal_impulse` are per-face window
  /// integrals since the start of the revolution ([m^3], [N s]).
  void sample(const BedGrains& grains, double time, const std::vector<double>& removed,
              const std::vector<double>& normal_impulse);
  /// The grains of `p` over the sample (over_sample of a sphere's or a body's centre):
  /// spheres as themselves, the members of `clumps` (when given) as their bodies. `placed` is
  /// the current wearing wall in the tester frame (the gaps are taken to it).
  BedGrains grains(const Particles& p, const Clumps* clumps, const meshes::SurfaceMesh& placed);
  /// True when a particle centred at x (tester frame) is one sample() counts: over the
  /// sample's footprint, above its base less 1 mm. Over ranks the tester gathers these.
  bool over_sample(const Vec3& x) const;
  /// Closes the revolution with the per-face removed volume and the per-contact total.
  RevolutionRecord& end_revolution(double time, const std::vector<double>& removed,
                                   double contact_total_removed);
  /// The open revolution's samples, and taking them back when a run continues inside it.
  const RevolutionSamples& open_samples() const { return open_; }
  void resume_samples(const RevolutionSamples& samples);
  const std::vector<RevolutionRecord>& history() const { return history_; }
  std::vector<RevolutionRecord>& history() { return history_; }

private:
  void update_height_map(const meshes::SurfaceMesh& placed);
  double surface_height(double x, double y) const;

  meshes::SampleGeometry geometry_;
  meshes::SampleFrame frame_; ///< sample <-> tester
  double layer_diameter_, steady_threshold_;
  int steady_revolutions_;
  int n_columns_ = 0;
  std::vector<double> column_y_; ///< [m] column midlines along the flow, sample frame
  std::vector<int> face_column_, face_label_, element_labels_;
  std::vector<char> wears_;
  // Height of the wear surface over the footprint, sample frame (rebuilt per revision).
  std::uint64_t height_revision_ = 0;
  int hx_ = 0, hy_ = 0;
  double cell_ = 0;
  std::vector<double> height_;
  RevolutionSamples open_; ///< the current revolution's samples
  std::vector<RevolutionRecord> history_;
};

} // namespace wear::dem
