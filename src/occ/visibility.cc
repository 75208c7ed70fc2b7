// visibility.cc -- the CGAL AABB tree behind visibility.h.
//
// Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
//
// The typedef ladder is the one of the CGAL 5.5 AABB tree examples
// (AABB_tree/AABB_triangle_3_example.cpp): kernel, triangle vector,
// primitive over the vector's iterators, AABB_traits, AABB_tree.  The
// kernel is Exact_predicates_inexact_constructions_kernel: do_intersect is
// an exact predicate, and only predicates are used here, so answers never
// depend on round-off.  CGAL needs the processor's rounding mode to be
// switchable (-frounding-math, set in Makefile.am) and links gmp and mpfr
// for its exact fallback.
//
// Queries list the intersected primitives with the documented
// all_intersected_primitives and skip the two owners there; a segment
// meets few triangles, so listing them all costs little.  The tree is built
// in radi_vis_create (tree.build()), never lazily inside a query, so that
// queries from several OpenMP threads only read it.
#include <config.h>
/* CGAL checks at start-up that the rounding mode can be switched; under
 * valgrind it cannot, and the check aborts every run.  The build always
 * compiles this file with -frounding-math (Makefile.am), which is what the
 * check is for, so it is left out: then `valgrind --tool=callgrind` counts
 * the instructions of a fill (the numbers of README's benchmark notes).
 * Under valgrind, the tree's interval filters round to nearest and near-
 * degenerate predicates may go either way; no test runs under it. */
#define CGAL_DISABLE_ROUNDING_MATH_CHECK 1

#include <algorithm>
#include <exception>
#include <iterator>
#include <new>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "util/util.h"
#include "occ/visibility.h"

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Segment_3 Segment;
typedef K::Triangle_3 Triangle;
typedef K::Iso_cuboid_3 Box;
typedef std::vector<Triangle>::const_iterator Iterator;
typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
typedef CGAL::AABB_traits<K, Primitive> Traits;
typedef CGAL::AABB_tree<Traits> Tree;

Point point(rad_vec3 v)
{
    return Point(v.x, v.y, v.z);
}

// An output iterator for all_intersected_primitives: remembers whether a
// primitive with an owner other than the two skipped ones came by.
class Unskipped_hit {
  public:
    typedef std::output_iterator_tag iterator_category;
    typedef void value_type;
    typedef void difference_type;
    typedef void pointer;
    typedef void reference;

    Unskipped_hit(const std::vector<Triangle> &tris, const std::vector<int> &owner, int a,
                  int b, bool *hit)
        : tris_(&tris), owner_(&owner), a_(a), b_(b), hit_(hit)
    {
    }
    Unskipped_hit &operator*() { return *this; }
    Unskipped_hit &operator++() { return *this; }
    Unskipped_hit operator++(int) { return *this; }
    Unskipped_hit &operator=(const Iterator &id)
    {
        int k = (*owner_)[static_cast<std::size_t>(id - tris_->begin())];
        if (k != a_ && k != b_)
            *hit_ = true;
        return *this;
    }

  private:
    const std::vector<Triangle> *tris_;
    const std::vector<int> *owner_;
    int a_, b_;
    bool *hit_;
};

// An output iterator that collects the owners of the listed primitives.
class Owner_list {
  public:
    typedef std::output_iterator_tag iterator_category;
    typedef void value_type;
    typedef void difference_type;
    typedef void pointer;
    typedef void reference;

    Owner_list(const std::vector<Triangle> &tris, const std::vector<int> &owner,
               std::vector<int> *out)
        : tris_(&tris), owner_(&owner), out_(out)
    {
    }
    Owner_list &operator*() { return *this; }
    Owner_list &operator++() { return *this; }
    Owner_list operator++(int) { return *this; }
    Owner_list &operator=(const Iterator &id)
    {
        out_->push_back((*owner_)[static_cast<std::size_t>(id - tris_->begin())]);
        return *this;
    }

  private:
    const std::vector<Triangle> *tris_;
    const std::vector<int> *owner_;
    std::vector<int> *out_;
};

} // namespace

struct rad_vis {
    std::vector<Triangle> tris; // never resized after the tree is built
    std::vector<int> owner;     // polygon of each triangle
    Tree tree;
};

// Fan triangulation of each polygon from its first vertex, leaving out
// degenerate triangles (exact colinearity test).
static void fan_triangles(rad_vis *v, const rad_vec3 *verts, const int *first, int npolys)
{
    for (int k = 0; k < npolys; k++)
        for (int a = first[k] + 1; a + 1 < first[k + 1]; a++) {
            Point p0 = point(verts[first[k]]), p1 = point(verts[a]), p2 = point(verts[a + 1]);
            if (CGAL::collinear(p0, p1, p2))
                continue;
            v->tris.push_back(Triangle(p0, p1, p2));
            v->owner.push_back(k);
        }
}

extern "C" rad_status radi_vis_create(rad_vis **vis, const rad_vec3 *verts, const int *first,
                                     int npolys, rad_error *err)
{
    *vis = nullptr;
    rad_vis *v = nullptr;
    try {
        v = new rad_vis;
        fan_triangles(v, verts, first, npolys);
        v->tree.insert(v->tris.begin(), v->tris.end());
        v->tree.build();
        *vis = v;
        return RAD_OK;
    } catch (const std::bad_alloc &) {
        delete v;
        return radi_fail(err, RAD_ERR_NOMEM, "out of memory for the visibility tree");
    } catch (const std::exception &e) {
        delete v;
        return radi_fail(err, RAD_ERR_INVALID, "visibility tree: %s", e.what());
    } catch (...) {
        delete v;
        return radi_fail(err, RAD_ERR_INVALID, "visibility tree: unknown exception");
    }
}

extern "C" void radi_vis_free(rad_vis *vis)
{
    delete vis;
}

extern "C" int radi_vis_triangles(const rad_vis *vis)
{
    return static_cast<int>(vis->tris.size());
}

// A query object for the segment pq: the segment, or the point when p = q
// (CGAL's Segment_3 must have distinct ends).
template <class Fn> static int with_query(rad_vec3 p, rad_vec3 q, Fn fn)
{
    try {
        Point a = point(p), b = point(q);
        if (a == b)
            return fn(a) ? 1 : 0;
        return fn(Segment(a, b)) ? 1 : 0;
    } catch (...) {
        return -1;
    }
}

extern "C" int radi_vis_segment_blocked(const rad_vis *vis, rad_vec3 p, rad_vec3 q, int skip_a,
                                       int skip_b)
{
    return with_query(p, q, [&](const auto &query) {
        bool hit = false;
        vis->tree.all_intersected_primitives(
            query, Unskipped_hit(vis->tris, vis->owner, skip_a, skip_b, &hit));
        return hit;
    });
}

extern "C" int radi_vis_segment_blocked_brute(const rad_vis *vis, rad_vec3 p, rad_vec3 q,
                                             int skip_a, int skip_b)
{
    return with_query(p, q, [&](const auto &query) {
        for (std::size_t k = 0; k < vis->tris.size(); k++) {
            int o = vis->owner[k];
            if (o != skip_a && o != skip_b && CGAL::do_intersect(query, vis->tris[k]))
                return true;
        }
        return false;
    });
}

extern "C" int radi_vis_box_polygons(const rad_vis *vis, rad_vec3 lo, rad_vec3 hi, int *owners)
{
    try {
        std::vector<int> hits;
        Box box(point(lo), point(hi));
        vis->tree.all_intersected_primitives(box, Owner_list(vis->tris, vis->owner, &hits));
        std::sort(hits.begin(), hits.end());
        hits.erase(std::unique(hits.begin(), hits.end()), hits.end());
        std::copy(hits.begin(), hits.end(), owners);
        return static_cast<int>(hits.size());
    } catch (...) {
        return -1;
    }
}
