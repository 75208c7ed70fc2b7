#!/usr/bin/env python3
"""pairref.py -- an independent form factor between two planar convex
quadrilaterals with convex solids between them, for the tests.

Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.

Nothing here is the program's method.  Each solid blocks as the convex hull
of its vertices (not as a list of faces, so the program's choice of which
faces a pair needs, src/occ/occsolid.c, is checked, not copied).  From a point x
of the outer quad the part of the inner quad that x sees is the quad less
the shadow of each solid: the solid cut to the slab between x's level and
the inner plane (its vertices there and the crossings of the segments
between its vertices, whose hull is the cut solid), projected from x onto
the inner plane, its 2-D convex hull.  The slab starts where the segments
from x to the inner quad can first meet the solid (a lower bound on its
distance from x over their length), not at x's level: cut there, the
solid's vertices project towards infinity, and hull edges through points
1e8 away lost 1e-5 of a nearly hidden pair's visible part (the pair of
tests/flush-pair.spec, against the same computation in 40 digits).  A
twisted inner quad is read as its bilinear surface, the surface the
program's kernel integrates over (src/ff/ffarea.c): the visible pieces, cut
in the projection on its plane, are lifted back onto it, so that their
edges on the quad's edges are the quad's own.  A convex polygon less a convex
polygon is cut into convex pieces, one per edge of the shadow (the part
outside that edge, then the rest goes on), and each piece adds the
point-to-polygon factor (Lambert 1760):
    F(x -> Q) = 1/(2 pi) | sum_k gamma_k n_x . (R_k x R_k+1) / |R_k x R_k+1| |.
The outer integral is adaptive: bilinear cells with tensor Gauss-Legendre
rules of 6 and 10 points a side, the cell with the largest difference split
in four, until the differences sum to TOL of the value, or of FLOOR times
the unoccluded factor U (the same integral with no solids) when the value
is smaller: the program's promise holds relative to the value down to pairs
hidden to FLOOR = 1e-4 of U, and absolutely below that (doc/design.md,
"Conventions"), so a reference for a nearly hidden pair needs no more.
That estimate can miss a kink that no point of a cell sees, like any such
rule: a test using it states a value that two starting grids agree on.

Usage: pairref.py SPEC [TOL [N]], SPEC a file of lines
    outer X Y Z X Y Z X Y Z X Y Z
    inner X Y Z ...
    solid X Y Z X Y Z ...           (any number of vertices, any number of solids)
prints "F ESTIMATE U" for F from the outer quad to the inner one, the
estimate of its error and the unoccluded factor U.
"""

import math, sys, heapq
def sub(a,b): return (a[0]-b[0],a[1]-b[1],a[2]-b[2])
def add(a,b): return (a[0]+b[0],a[1]+b[1],a[2]+b[2])
def mul(a,s): return (a[0]*s,a[1]*s,a[2]*s)
def dot(a,b): return a[0]*b[0]+a[1]*b[1]+a[2]*b[2]
def cross(a,b): return (a[1]*b[2]-a[2]*b[1],a[2]*b[0]-a[0]*b[2],a[0]*b[1]-a[1]*b[0])
def norm(a): return math.sqrt(dot(a,a))
def unit(a): n=norm(a); return (a[0]/n,a[1]/n,a[2]/n)
def newell(P):
    n=(0,0,0)
    for i in range(len(P)): n=add(n,cross(P[i-1],P[i]))
    return n
def hull2(pts):
    """2-D convex hull, counter-clockwise (Andrew's monotone chain, 1979)."""
    pts=sorted(set(pts))
    if len(pts)<3: return pts
    def cr(o,a,b): return (a[0]-o[0])*(b[1]-o[1])-(a[1]-o[1])*(b[0]-o[0])
    lo=[];up=[]
    for p in pts:
        while len(lo)>=2 and cr(lo[-2],lo[-1],p)<=0: lo.pop()
        lo.append(p)
    for p in reversed(pts):
        while len(up)>=2 and cr(up[-2],up[-1],p)<=0: up.pop()
        up.append(p)
    return lo[:-1]+up[:-1]
def clip(poly,a,b,left):
    """The part of convex poly left (or right) of line a->b (Sutherland & Hodgman 1974)."""
    out=[]; n=len(poly)
    def side(p):
        s=(b[0]-a[0])*(p[1]-a[1])-(b[1]-a[1])*(p[0]-a[0]); return s if left else -s
    for i in range(n):
        p=poly[i]; q=poly[(i+1)%n]; sp=side(p); sq=side(q)
        if sp>=0: out.append(p)
        if (sp>0 and sq<0) or (sp<0 and sq>0):
            t=sp/(sp-sq); out.append((p[0]+t*(q[0]-p[0]),p[1]+t*(q[1]-p[1])))
    return out
def area2(p): return abs(sum(p[i-1][0]*p[i][1]-p[i][0]*p[i-1][1] for i in range(len(p))))/2
def minus(pieces,h):
    """Convex pieces less convex polygon h: for each edge, the part outside it."""
    res=[]
    for poly in pieces:
        rest=poly
        for i in range(len(h)):
            a=h[i]; b=h[(i+1)%len(h)]
            o=clip(rest,a,b,False)
            if len(o)>=3 and area2(o)>0: res.append(o)
            rest=clip(rest,a,b,True)
            if len(rest)<3: break
    return res
class Pair:
    def __init__(s,O,T,solids):
        s.O=O; s.T=T; s.solids=solids
        s.nO=unit(newell(O)); s.nT=unit(newell(T))
        s.t0=T[0]
        e=sub(T[1],T[0]); s.u=unit(sub(e,mul(s.nT,dot(s.nT,e))))  # in T's plane, even
        s.w=cross(s.nT,s.u)          # when T is twisted: (u, w, nT) orthonormal
        s.Q2=[s.to2(p) for p in T]
        s.T2=hull2(s.Q2)
        big=max(abs(c) for p in T for c in p)
        s.twisted=len(T)==4 and max(abs(dot(s.nT,sub(p,s.t0))) for p in T)>64*2.2e-16*big
    def to2(s,p): d=sub(p,s.t0); return (dot(d,s.u),dot(d,s.w))
    def to3(s,q):
        """The point of the inner quad over q: on its plane, or on a twisted
        quad's bilinear surface (the surface the program's kernel integrates
        over, src/ff/ffarea.c, so that its edges are the quad's own)."""
        if not s.twisted: return add(s.t0,add(mul(s.u,q[0]),mul(s.w,q[1])))
        Q=s.Q2; a,b=0.5,0.5
        for _ in range(8):              # Newton on bil(Q2, a, b) = q
            p=bil(Q,a,b)
            pa=(Q[1][0]-Q[0][0])*(1-b)+(Q[2][0]-Q[3][0])*b, (Q[1][1]-Q[0][1])*(1-b)+(Q[2][1]-Q[3][1])*b
            pb=(Q[3][0]-Q[0][0])*(1-a)+(Q[2][0]-Q[1][0])*a, (Q[3][1]-Q[0][1])*(1-a)+(Q[2][1]-Q[1][1])*a
            det=pa[0]*pb[1]-pa[1]*pb[0]; rx,ry=q[0]-p[0],q[1]-p[1]
            da=(rx*pb[1]-ry*pb[0])/det; db=(pa[0]*ry-pa[1]*rx)/det
            a+=da; b+=db
            if abs(da)+abs(db)<1e-17: break
        return bil(s.T,a,b)
    def shadow(s,x,V):
        """Shadow from x of the hull of V on the inner plane, in its 2-D frame."""
        h=dot(s.nT,sub(s.t0,x))          # x's height over T's plane (signed)
        def lev(v): return dot(s.nT,sub(v,x))/h   # 0 at x's level, 1 on T's plane
        # A segment from x to a point y of the inner quad meets the solid
        # only where lev >= D / |y - x|, D <= the solid's distance from x:
        # cut there (not at x's level, where the cut's vertices project
        # towards infinity and their hull edges lose digits) and at the
        # inner plane (a solid behind it hides nothing).  D: the nearest
        # vertex along the direction from x to the vertices' mean.
        c=mul(V[0],0.0)
        for v in V: c=add(c,mul(v,1.0/len(V)))
        n=sub(c,x); nn=norm(n)
        D=min(dot(n,sub(v,x)) for v in V)/nn if nn>0 else 0.0
        near=max(1e-9,0.999*D/max(norm(sub(t,x)) for t in s.T))
        def inside(l): return near<=l<=1
        keep=[v for v in V if inside(lev(v))]
        pts=list(keep)
        for i in range(len(V)):
            for j in range(i+1,len(V)):
                a,b=lev(V[i]),lev(V[j])
                for cut in (near,1.0):
                    if (a<cut)!=(b<cut):
                        t=(cut-a)/(b-a); pts.append(add(V[i],mul(sub(V[j],V[i]),t)))
        if not pts: return None
        proj=[]
        for v in pts:
            l=lev(v); proj.append(s.to2(add(x,mul(sub(v,x),1/l))))
        return hull2(proj)
    def visible(s,x):
        """F from the point x (outer normal) to the part of the inner quad it sees."""
        pcs=[s.T2]
        for V in s.solids:
            sh=s.shadow(x,V)
            if sh and len(sh)>=3: pcs=minus(pcs,sh)
            if not pcs: return 0.0
        tot=0.0
        for p in pcs:
            P=[s.to3(q) for q in p]; sm=0.0
            for k in range(len(P)):
                r0=sub(P[k-1],x); r1=sub(P[k],x); c=cross(r0,r1); cn=norm(c)
                if cn>0: sm+=math.atan2(cn,dot(r0,r1))*dot(s.nO,c)/cn
            tot+=abs(sm)/(2*math.pi)
        return tot
def gl(n):
    """Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n)."""
    xs=[];ws=[]
    for i in range(1,n+1):
        t=math.cos(math.pi*(i-0.25)/(n+0.5))
        for _ in range(100):
            p0,p1=1.0,t
            for k in range(2,n+1): p0,p1=p1,((2*k-1)*t*p1-(k-1)*p0)/k
            dp=n*(t*p1-p0)/(t*t-1); dt=p1/dp; t-=dt
            if abs(dt)<1e-16: break
        xs.append(t); ws.append(2/((1-t*t)*dp*dp))
    return xs,ws
G={n:gl(n) for n in (6,10)}
def bil(P,u,v):
    """The bilinear map of quad P (points of 2 or 3 coordinates) at (u, v)."""
    w=((1-u)*(1-v),u*(1-v),u*v,(1-u)*v)
    return tuple((a*w[0]+b*w[1])+(c*w[2]+d*w[3]) for a,b,c,d in zip(*P))
def rule(pr,P,n):
    """n x n Gauss product on the bilinear cell P (with its Jacobian)."""
    xs,ws=G[n]; s=0.0
    for a,wa in zip(xs,ws):
        u=(a+1)/2
        for b,wb in zip(xs,ws):
            v=(b+1)/2
            du=add(mul(sub(P[1],P[0]),1-v),mul(sub(P[2],P[3]),v))
            dv=add(mul(sub(P[3],P[0]),1-u),mul(sub(P[2],P[1]),u))
            s+=wa*wb*0.25*norm(cross(du,dv))*pr.visible(bil(P,u,v))
    return s
FLOOR = 1e-4  # the promise's floor, relative to the unoccluded factor (docstring)

def integrate(pr,tol=1e-11,maxit=20000,N=4,floor=0.0):
    """F and its estimate: N x N cells, the worst split until the estimates
    sum to tol of max(|F|, floor)."""
    O=pr.O; cells=[]; AO=norm(newell(O))/2
    def push(P):
        a=rule(pr,P,6); b=rule(pr,P,10); heapq.heappush(cells,(-abs(a-b),id(P),P,b))
    for i in range(N):
        for j in range(N):
            push([bil(O,i/N,j/N),bil(O,(i+1)/N,j/N),bil(O,(i+1)/N,(j+1)/N),bil(O,i/N,(j+1)/N)])
    it=0
    while True:
        tot=sum(c[3] for c in cells); err=sum(-c[0] for c in cells)
        if err<=tol*max(abs(tot),floor*AO) or it>=maxit: break
        e,_,P,q=heapq.heappop(cells)
        m=lambda a,b: mul(add(a,b),0.5)
        ab=m(P[0],P[1]); bc=m(P[1],P[2]); cd=m(P[2],P[3]); da=m(P[3],P[0]); c=m(ab,cd)
        for Q in ([P[0],ab,c,da],[ab,P[1],bc,c],[c,bc,P[2],cd],[da,c,cd,P[3]]): push(Q)
        it+=1
    return tot/AO, err/AO, it


def main(argv):
    O = T = None
    solids = []
    for line in open(argv[1]):
        f = line.split()
        if not f or f[0].startswith('#'):
            continue
        v = [float(t) for t in f[1:]]
        pts = [tuple(v[k:k + 3]) for k in range(0, len(v), 3)]
        if f[0] == 'outer':
            O = pts
        elif f[0] == 'inner':
            T = pts
        elif f[0] == 'solid':
            solids.append(pts)
    tol = float(argv[2]) if len(argv) > 2 else 1e-11
    n = int(argv[3]) if len(argv) > 3 else 4
    U, _, _ = integrate(Pair(O, T, []), tol, N=n)
    F, E, _ = integrate(Pair(O, T, solids), tol, N=n, floor=FLOOR * abs(U))
    print('%.17g %.3g %.17g' % (F, E, U))


if __name__ == '__main__':
    main(sys.argv)
