// Contacts where the sample meets its holder: the sample's sides and bottom and the holder's
// pocket are covered faces, and the edges where they meet the wear face and the rim are
// junctions (MeshWall::contact_ownership, system_contacts.cc). Each case places one sphere
// (r = 4 mm, no gravity) pressed into the surfaces at the seam and compares its force with the
// Hertz force of the one contact it should have, F = 4/3 E* sqrt(r) delta^1.5.
#include "tests/dem/dem_fixtures.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace wear::dem;
using namespace wear::dem::testing;
using wear::meshes::Vec3;
namespace label = wear::meshes::label;

namespace {

const double r = 4e-3, e_star = 5e7 / (2 * (1 - 0.25 * 0.25));
double hertz(double delta) {
  return 4.0 / 3.0 * e_star * std::sqrt(r) * std::pow(delta, 1.5);
}

/// The sample box [-hx, hx] x [-hy, hy] x [0, T], its top (the wear face) moved by dz and its
/// +x and +y sides by dx and dy: a worn sample sunk into its holder, or parted from its
/// pocket's walls.
wear::meshes::SurfaceMesh sample_box(double hx, double hy, double T, double dz, double dx,
                                     double dy) {
  wear::meshes::SurfaceMesh m;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        m.vertices.push_back({(2 * i - 1) * hx + i * dx, (2 * j - 1) * hy + j * dy, k * (T + dz)});
  const auto v = [](int i, int j, int k) { return std::uint32_t(i + 2 * j + 4 * k); };
  const auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d,
                        int l) { // counter-clockwise seen from outside
    m.triangles.push_back({a, b, c});
    m.triangles.push_back({a, c, d});
    m.face_labels.insert(m.face_labels.end(), 2, l);
  };
  quad(v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1), label::base);
  quad(v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0), label::bottom);
  quad(v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1), label::side);
  quad(v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0), label::side);
  quad(v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0), label::side);
  quad(v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1), label::side);
  REQUIRE(wear::meshes::enclosed_volume(m) == Approx(4 * (hx + dx / 2) * (hy + dy / 2) * (T + dz)));
  return m;
}

struct Seam {
  System system;
  int sample = 0, holder = 0;
};

/// The sample (its top moved by dz, its +x and +y sides by dx and dy) in the holder frame of
/// meshes::generate_holder, covered faces named or not, one sphere at `centre`, set up.
void set_up(Seam& s, double dz, double dx, double dy, bool covered, const Vec3& centre) {
  wear::meshes::SampleGeometry g;
  wear::meshes::TesterGeometry t;
  auto& sys = s.system;
  sys.settings.gravity = {0, 0, 0};
  const int m = add_gravel(sys, 0.5, 0.5, 0.0);
  const auto box = sample_box(g.width / 2, g.length / 2, g.thickness, dz, dx, dy);
  s.sample = sys.add_wall(
      MeshWall(box, m, {}, true, "sample",
               covered ? std::vector<int>{label::side, label::bottom} : std::vector<int>{}));
  s.holder = sys.add_wall(MeshWall(wear::meshes::generate_holder(g, t), m, {}, false, "holder",
                                   covered ? std::vector<int>{label::pocket} : std::vector<int>{}));
  sys.particles.add(centre, {}, r, 2650, m);
  sys.setup();
}

/// Contact-steps of one step on the sample's wear face and on its other faces.
std::pair<double, double> sample_contact_steps(Seam& s) {
  s.system.run(1);
  const auto wi = s.system.wear_integrals(s.sample);
  const auto& mesh = s.system.wall(s.sample).mesh();
  double on_wear_face = 0, elsewhere = 0;
  for (std::size_t k = 0; k < mesh.n_faces(); ++k)
    (mesh.face_labels[k] == label::base ? on_wear_face : elsewhere) += wi.contact_steps[k];
  return {on_wear_face, elsewhere};
}

} // namespace

TEST_CASE("a sphere on the flush junction of a sample and its holder has one contact",
          "[dem][walls][holder]") {
  // The rim top and the wear face form one plane z = T. A sphere pressed delta into that plane
  // 0.05 r beside the junction also overlaps the other wall's edge there
  // (r - sqrt((0.05 r)^2 + (r - delta)^2) > 0 for delta > 0.00125 r); on one flat wall it
  // would have one contact, F(delta) along +z. With the sides, bottom and pocket covered the
  // junction's edges are dropped for the face under the sphere: the force is the flat wall's
  // to round-off, and the sample's sides take no wear. Without covering, the edge contact adds
  // about 85 % (the test would fail).
  const double delta = 5e-5, hx = wear::meshes::SampleGeometry{}.width / 2;
  const double T = wear::meshes::SampleGeometry{}.thickness;
  for (const bool covered : {true, false})
    for (const double side : {1.0, -1.0}) { // over the rim, over the wear face
      Seam s;
      set_up(s, 0, 0, 0, covered, {hx + side * 0.05 * r, 0.013, T + r - delta});
      const Vec3 f = s.system.particles.force[0];
      INFO((covered ? "covered" : "not covered")
           << ", centre over the " << (side > 0 ? "rim" : "wear face"));
      if (!covered) {
        CHECK(norm(f) > 1.5 * hertz(delta)); // the double contact the covering removes
        continue;
      }
      CHECK(f.z == Approx(hertz(delta)).epsilon(1e-9));
      CHECK(std::hypot(f.x, f.y) < 1e-9 * hertz(delta));
      const auto [on_wear_face, elsewhere] = sample_contact_steps(s);
      CHECK(elsewhere == 0);
      if (side > 0)
        CHECK(on_wear_face == 0); // the rim took it
      else
        CHECK(on_wear_face > 0);
    }
}

TEST_CASE("a worn sample's seam with its holder holds a sphere on the deeper edge",
          "[dem][walls][holder]") {
  // The failure this guards against (the reference study, plain sample, revolution 14): the
  // wear face had sunk 85 um below the rim, and a particle whose centre lay over the seam had
  // the sample's and the rim's junction edges as its closest features on both walls. Junction
  // edges gave no contact then; the particle fell through the seam and was thrown out of the
  // pocket at 47 m/s. Now a junction contact stands where no other wall's is as deep, and of
  // two junction contacts the deeper one: the force is that edge's Hertz force along the
  // line from the edge to the centre.
  const wear::meshes::SampleGeometry g;
  const double hx = g.width / 2, T = g.thickness, delta = 5e-5, y = 0.013;
  struct Case {
    const char* what;
    double dz, dx;    // the sample's top and +x side moved [m]
    double x;         // the centre's x [m]
    bool sample_edge; // the contact is on the sample's edge (else the rim's)
  };
  const Case cases[] = {
      {"the wear face 85 um below the rim, 1 um parted, centre over the gap", -85e-6, -1e-6,
       hx - 0.5e-6, false},
      {"level, 4 um parted, centre 1 um from the rim's edge", 0, -4e-6, hx - 1e-6, false},
      {"level, 4 um parted, centre 1 um from the sample's edge", 0, -4e-6, hx - 3e-6, true},
      {"the sample 100 um proud of the rim, centre 0.05 r beyond its edge", 100e-6, 0,
       hx + 0.05 * r, true},
  };
  for (const auto& c : cases) {
    INFO(c.what);
    const Vec3 edge = c.sample_edge ? Vec3{hx + c.dx, y, T + c.dz} : Vec3{hx, y, T};
    // The centre at r - delta from the edge that holds it, in the plane y = const.
    const double ex = c.x - edge.x, ez = std::sqrt(std::pow(r - delta, 2) - ex * ex);
    const Vec3 centre{c.x, y, edge.z + ez};
    Seam s;
    set_up(s, c.dz, c.dx, 0, true, centre);
    const Vec3 f = s.system.particles.force[0];
    const Vec3 n = (centre - edge) * (1 / (r - delta));
    CHECK(norm(f) == Approx(hertz(delta)).epsilon(1e-6));
    CHECK(dot(f, n) == Approx(hertz(delta)).epsilon(1e-6));
    const auto [on_wear_face, elsewhere] = sample_contact_steps(s);
    CHECK(elsewhere == 0); // the covered sides take nothing, also from an edge contact
    CHECK((on_wear_face > 0) == c.sample_edge);
  }
}

TEST_CASE("a sample's corner standing proud of its holder holds a sphere on its vertex",
          "[dem][walls][holder]") {
  // The vertex form of a junction: the sample 100 um proud of the rim, the centre beyond its
  // corner diagonally, over the rim but out of the rim's reach. The closest feature is the
  // wear face's corner vertex, where the uncovered face meets two covered sides: a junction
  // judged on the wear face's edges alone. It holds the sphere with its Hertz force along
  // the line from the vertex to the centre, and its wear goes to the wear face only (the
  // vertex's share of each face taken over the uncovered faces).
  const wear::meshes::SampleGeometry g;
  const double hx = g.width / 2, hy = g.length / 2, T = g.thickness, delta = 5e-5;
  const double dz = 100e-6, e = 0.05 * r;
  const Vec3 corner{hx, hy, T + dz};
  const Vec3 centre{hx + e, hy + e, T + dz + std::sqrt(std::pow(r - delta, 2) - 2 * e * e)};
  REQUIRE(centre.z - T > r); // the rim's face is out of reach
  Seam s;
  set_up(s, dz, 0, 0, true, centre);
  const Vec3 f = s.system.particles.force[0];
  const Vec3 n = (centre - corner) * (1 / (r - delta));
  CHECK(norm(f) == Approx(hertz(delta)).epsilon(1e-6));
  CHECK(dot(f, n) == Approx(hertz(delta)).epsilon(1e-6));
  const auto [on_wear_face, elsewhere] = sample_contact_steps(s);
  CHECK(on_wear_face > 0);
  CHECK(elsewhere == 0);
}
