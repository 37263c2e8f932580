/*
 * The Embree anchor of `cargo bench -p render-benches --bench bvh` (issue 33).
 *
 * Embree 3 (Intel's ray tracing kernels, Debian's libembree-dev) asked what the
 * crate's BVH is asked: one triangle mesh, rays one at a time (rtcIntersect1), the
 * closest hit of each. The mesh is handed over as Embree's documentation recommends,
 * a shared buffer of float3 vertices and one of uint3 indices (no copy), and built
 * on one thread (device "threads=1") at the default quality, MEDIUM. The scene
 * flags stay the default: not RTC_SCENE_FLAG_ROBUST, so Embree's triangle test is
 * its fast one, not watertight. Compiled by build.rs only when the header
 * <embree3/rtcore.h> is found; linked with -lembree3.
 */
#include <embree3/rtcore.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>

/* The device made once per process: one build thread, and no console output. */
static RTCDevice device(void) {
    static RTCDevice d = NULL;
    if (d == NULL) {
        d = rtcNewDevice("threads=1,verbose=0");
    }
    return d;
}

/* "3.13.5": the library's version, for the bench's line. */
const char *embree_anchor_version(void) { return RTC_VERSION_STRING; }

/*
 * A scene of one triangle mesh: vertex_count vertices, three floats each, read in
 * place (Embree loads 16 bytes at a time, so `vertices` must be readable one float
 * past the last vertex), and triangle_count triangles of three indices. Primitive
 * i of the scene is triangle i. NULL when Embree refuses (rtcGetDeviceError says
 * why; the Rust side reports it).
 */
RTCScene embree_anchor_build(const float *vertices, size_t vertex_count,
                             const uint32_t *indices, size_t triangle_count) {
    RTCDevice d = device();
    if (d == NULL) {
        return NULL;
    }
    RTCScene scene = rtcNewScene(d);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_MEDIUM);
    RTCGeometry mesh = rtcNewGeometry(d, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(mesh, RTC_BUILD_QUALITY_MEDIUM);
    rtcSetSharedGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                               vertices, 0, 3 * sizeof(float), vertex_count);
    rtcSetSharedGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                               indices, 0, 3 * sizeof(uint32_t), triangle_count);
    rtcCommitGeometry(mesh);
    rtcAttachGeometry(scene, mesh);
    rtcReleaseGeometry(mesh); /* the scene holds it now */
    rtcCommitScene(scene);
    if (rtcGetDeviceError(d) != RTC_ERROR_NONE) {
        rtcReleaseScene(scene);
        return NULL;
    }
    return scene;
}

/* Frees a scene of embree_anchor_build. */
void embree_anchor_release(RTCScene scene) { rtcReleaseScene(scene); }

/* The last error Embree reported on the device, as its enum's number (0: none). */
int embree_anchor_error(void) {
    RTCDevice d = device();
    return d == NULL ? (int)rtcGetDeviceError(NULL) : (int)rtcGetDeviceError(d);
}

/*
 * The closest hit of each of ray_count rays, one rtcIntersect1 call each. Ray i is
 * rays[6 i .. 6 i + 6]: origin x, y, z, then direction x, y, z; its segment is
 * [0, infinity). Returns how many rays hit. When `t` is not NULL, t[i] is ray i's
 * distance to its hit (infinity on a miss) and prim[i] the triangle's index
 * (UINT32_MAX on a miss).
 */
size_t embree_anchor_trace(RTCScene scene, const float *rays, size_t ray_count,
                           float *t, uint32_t *prim) {
    struct RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    size_t hits = 0;
    for (size_t i = 0; i < ray_count; i++) {
        const float *r = rays + 6 * i;
        struct RTCRayHit rh; /* Embree aligns the type to 16 bytes */
        rh.ray.org_x = r[0];
        rh.ray.org_y = r[1];
        rh.ray.org_z = r[2];
        rh.ray.dir_x = r[3];
        rh.ray.dir_y = r[4];
        rh.ray.dir_z = r[5];
        rh.ray.tnear = 0.0f;
        rh.ray.tfar = INFINITY;
        rh.ray.time = 0.0f;
        rh.ray.mask = UINT32_MAX;
        rh.ray.id = 0;
        rh.ray.flags = 0;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene, &context, &rh);
        int hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        hits += (size_t)hit;
        if (t != NULL) {
            t[i] = hit ? rh.ray.tfar : INFINITY;
            prim[i] = hit ? rh.hit.primID : UINT32_MAX;
        }
    }
    return hits;
}
