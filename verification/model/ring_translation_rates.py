# Independent 50-digit computation (mpmath) of the spurious Rayleigh quotient
# of a rigid translation on one ring element: the energy integrated directly
# from the Hermite interpolant, not through ring_stiffness(). Prints the
# observed rate per halving; quoted in test_ring_element.cpp.
# Run: python3 verification/model/ring_translation_rates.py
from mpmath import mp, mpf, cos, sin, pi, sqrt
mp.dps = 50
R = mpf('0.501'); EI = mpf(1); 
def H(xi,l): return [1-3*xi**2+2*xi**3, l*(xi-2*xi**2+xi**3), 3*xi**2-2*xi**3, l*(-xi**2+xi**3)]
def H1(xi,l): return [(-6*xi+6*xi**2)/l, (1-4*xi+3*xi**2), (6*xi-6*xi**2)/l, (-2*xi+3*xi**2)]
def H2(xi,l): return [(-6+12*xi)/l**2, (-4+6*xi)/l, (6-12*xi)/l**2, (-2+6*xi)/l]
import mpmath
def q(n, part):
    dt = 2*pi/n; l = R*dt
    t = [1, 1+dt]
    u = [cos(t[0]), -sin(t[0])/R, cos(t[1]), -sin(t[1])/R]
    v = [-sin(t[0]), -cos(t[0])/R, -sin(t[1]), -cos(t[1])/R]
    f = lambda xi: ( (sum(a*b for a,b in zip(H2(xi,l),u)) - sum(a*b for a,b in zip(H1(xi,l),v))/R)**2 if part=='b' else
                     (sum(a*b for a,b in zip(H1(xi,l),v)) + sum(a*b for a,b in zip(H(xi,l),u))/R)**2 )
    g = lambda xi: sum(a*b for a,b in zip(H(xi,l),u))**2 + sum(a*b for a,b in zip(H(xi,l),v))**2
    return mpmath.quad(f,[0,1])/mpmath.quad(g,[0,1])
for part in 'bm':
    prev=None
    for n in [10,20,40,80,160,320,640,1280]:
        val=q(n,part)
        if prev: print(part, n, mpmath.nstr(mpmath.log(prev/val,2),6))
        prev=val
