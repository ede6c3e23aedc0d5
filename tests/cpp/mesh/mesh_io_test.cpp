#include "mesh/mesh_io.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "geometry/error.h"
#include "mesh/sample_meshes.h"

using namespace holefill;

namespace {
void expectSameMesh(const TriangleMesh& a, const TriangleMesh& b, double tol) {
  ASSERT_EQ(a.vertices.rows(), b.vertices.rows());
  ASSERT_EQ(a.triangles.rows(), b.triangles.rows());
  EXPECT_LE((a.vertices - b.vertices).cwiseAbs().maxCoeff(), tol);
  EXPECT_TRUE((a.triangles.array() == b.triangles.array()).all());
}
}  // namespace

TEST(MeshIo, RoundTripsEveryFormat) {
  const TriangleMesh m = samples::icosphere(2, 3.25);
  for (const std::string ext : {"obj", "off", "ply"}) expectSameMesh(parseMesh(formatMesh(m, ext), ext), m, 0.0);
  // STL stores float corners and no indices: welding bit-identical corners restores the sharing.
  const TriangleMesh stl = parseMesh(formatMesh(m, "stl"), "stl");
  EXPECT_EQ(stl.vertices.rows(), m.vertices.rows());
  EXPECT_EQ(stl.triangles.rows(), m.triangles.rows());
}

TEST(MeshIo, ReadsPolygonsNegativeIndicesAndBinaryPly) {
  const TriangleMesh quad = parseMesh("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4/1/1 -3/2/2 -2/3/3 -1/4/4\n", "obj");
  EXPECT_EQ(quad.triangles.rows(), 2);
  EXPECT_EQ(quad.triangles.row(1), Eigen::RowVector3i(0, 2, 3));
  const TriangleMesh off = parseMesh("OFF\n# comment\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n", "off");
  EXPECT_EQ(off.triangles.rows(), 1);
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                    "property uchar red\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const float p[9] = {0, 0, 0, 2, 0, 0, 0, 2, 0};
  for (int i = 0; i < 3; ++i) {
    ply.append(reinterpret_cast<const char*>(p + 3 * i), 12);
    ply.push_back('\x07');
  }
  ply.push_back('\x03');
  const int idx[3] = {0, 1, 2};
  ply.append(reinterpret_cast<const char*>(idx), 12);
  const TriangleMesh bin = parseMesh(ply, "ply");
  EXPECT_EQ(bin.vertices(1, 0), 2.0);
  EXPECT_EQ(bin.triangles.row(0), Eigen::RowVector3i(0, 1, 2));
}

TEST(MeshIo, CorruptFilesGiveClearErrors) {
  auto message = [](const std::string& bytes, const std::string& ext) -> std::string {
    try {
      parseMesh(bytes, ext, "in." + ext);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message("", "obj").find("empty"), std::string::npos);
  EXPECT_NE(message("v 0 0 0\nv 1 0 0\nf 1 2 3\n", "obj").find("out of range"), std::string::npos);
  EXPECT_NE(message("v 0 nan 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "obj").find("not finite"), std::string::npos);
  EXPECT_NE(message("OFF\n999999999 1 0\n0 0 0\n", "off").find("truncated"), std::string::npos);
  EXPECT_NE(message("OFF\n3 1 0\n0 0 0\n1 0 0\n", "off").find("three numbers"), std::string::npos);
  EXPECT_NE(message("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n\x01\x02",
                    "ply").find("truncated"), std::string::npos);
  EXPECT_NE(message("garbage", "stl").find("neither"), std::string::npos);
  EXPECT_NE(message("v 0 0 0\n", "obj").find("no triangles"), std::string::npos);
  EXPECT_NE(message("v 0 0 0", "dxf").find("unsupported"), std::string::npos);
  EXPECT_THROW(readMesh("/nonexistent/x.obj"), Error);
  // Header and body that disagree (issue 22: a PLY declaring fewer faces than it holds was read
  // up to its count, and the rest silently dropped).
  const std::string plyHead = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                              "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  EXPECT_NO_THROW(parseMesh(plyHead + "3 0 1 2\n", "ply"));
  EXPECT_NE(message(plyHead + "3 0 1 2\n3 0 2 3\n", "ply").find("more data than the header"), std::string::npos);
  EXPECT_NE(message("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n", "off").find("more data than the header"),
            std::string::npos);
}

// Found by fuzzing (tests/fuzz, UBSan): an OFF count near 2^63 overflowed the size check, and a
// PLY face list of floats (3.6e37) was converted to an integer index, both undefined behaviour.
TEST(MeshIo, FuzzedCountsAndIndicesAreRefused) {
  const auto refused = [](const std::string& bytes, const std::string& ext, const std::string& why) {
    try {
      parseMesh(bytes, ext);
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted: " << bytes;
  };
  refused("OFF\n9223372036854775807 1 0\n0 0 0\n", "off", "do not fit");
  refused("OFF\n3 9223372036854775807 0\n0 0 0\n", "off", "do not fit");
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "element face 1\nproperty list uchar float vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  refused(head + "3 0 1 3.55556e+37\n", "ply", "not an integer");
  refused(head + "3 0 1 1.5\n", "ply", "not an integer");
  EXPECT_EQ(parseMesh(head + "3 0 1 2\n", "ply").triangles.rows(), 1);  // float-typed but whole: still an index
}

TEST(MeshIo, WritesAtomically) {
  const TriangleMesh m = samples::icosphere(1);
  EXPECT_THROW(writeMesh(m, "/nonexistent-folder/out.obj"), Error);
  const std::string path = ::testing::TempDir() + "/holefill_io_test.off";
  writeMesh(m, path);
  expectSameMesh(readMesh(path), m, 0.0);
  std::remove(path.c_str());
}
