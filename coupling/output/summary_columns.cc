// summary.csv's per-revolution columns (summary_columns.h): one row per record of the tester's
// evaluation, numbers in SI units as the column names say, full precision.
#include "coupling/output/summary_columns.h"

#include "meshes/surface_mesh.h"

#include <iomanip>

namespace wear::coupling {

void write_summary_header(std::ostream& c, int n_columns, const std::vector<int>& element_labels) {
  c << "revolution,time_s,wear_volume_m3,wear_volume_cumulative_m3,wear_volume_other_m3,"
       "contact_total_wear_volume_m3";
  for (int k = 1; k <= n_columns; ++k)
    c << ",column" << k << "_wear_m3";
  for (int l : element_labels)
    c << "," << meshes::label::name(l) << "_wear_m3";
  c << ",mean_element_increment_m3,normal_force_mean_N,normal_force_std_N";
  for (int k = 1; k <= n_columns; ++k)
    c << ",column" << k << "_force_mean_N,column" << k << "_force_std_N";
  c << ",bottom_speed_mean_m_s,bottom_speed_std_m_s,bottom_spin_mean_rad_s,"
       "bottom_spin_std_rad_s,bottom_count,speed_over_sample_mean_m_s,cv_speed,"
       "bed_height_mean_m,cv_bed_height,wear_rate_mean_m3_s,cv_wear_rate,steady,"
       "steady_revolution,fit_from_revolution,fit_linear_a_m3,fit_linear_r2,fit_quadratic_b_m3,"
       "fit_quadratic_c_m3,fit_quadratic_r2,swept_volume_m3,applied_volume_m3,"
       "enclosed_volume_loss_m3,min_angle_deg,distortion,wall_seconds,particle_steps_per_s";
}

void write_summary_row(std::ostream& c, const dem::RevolutionRecord& r,
                       const std::vector<int>& element_labels) {
  c << std::setprecision(10);
  c << r.revolution << "," << r.time << "," << r.wear_volume << "," << r.wear_volume_cumulative
    << "," << r.wear_volume_other << "," << r.contact_total_wear_volume;
  for (double v : r.column_wear)
    c << "," << v;
  for (int l : element_labels) {
    const auto it = r.element_wear.find(l);
    c << "," << (it == r.element_wear.end() ? 0.0 : it->second);
  }
  c << "," << r.mean_element_increment << "," << r.normal_force.mean << "," << r.normal_force.std;
  for (const auto& s : r.column_normal_force)
    c << "," << s.mean << "," << s.std;
  c << "," << r.bottom_speed.mean << "," << r.bottom_speed.std << "," << r.bottom_spin.mean << ","
    << r.bottom_spin.std << "," << r.bottom_count << "," << r.speed_over_sample.mean << ","
    << r.speed_over_sample.cv() << "," << r.bed_height.mean << "," << r.bed_height.cv() << ","
    << r.wear_rate.mean << "," << r.wear_rate.cv() << "," << (r.steady ? 1 : 0) << ","
    << r.steady_revolution << "," << r.fits_from << "," << r.fits.a << "," << r.fits.r2_linear
    << "," << r.fits.b << "," << r.fits.c << "," << r.fits.r2_quadratic << "," << r.swept_volume
    << "," << r.applied_volume << "," << r.enclosed_volume_loss << "," << r.min_angle_deg << ",\""
    << r.distortion << "\"," << r.wall_seconds << "," << r.particle_steps_per_second;
}

} // namespace wear::coupling
