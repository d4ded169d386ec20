# Reference for tests/elastic_layer.rs: the centre settlement factor I (w = q B (1 - nu^2) I / E)
# of a uniform flexible square (side B = 2a, a = 1) on a layer of depth h (argument: h/a) over a
# rigid base, rough (bonded, the default) or smooth (frictionless: third argument "smooth"), nu = 0.3,
# in the wavenumber domain with mpmath (independent of liftoff):
# I = (4/pi) [ln(1 + sqrt 2) - int_0^{pi/4} int_0^inf (1 - K(t)) R J1(t R/h)/t dt dtheta], R = 1/cos(theta).
# 1 - K(t) written out from the two closed forms (Burmister's rough base; the smooth base's
# K = (cosh 2t - 1)/(sinh 2t + 2t)), not taken from the library.
# Usage: python3 tests/layer_settlement_reference.py 2 [rough|smooth] [digits]
#   (prints I for 12 and 24 theta points)
from mpmath import mp, mpf, exp, cosh, sinh, besselj, quad, log, sqrt, pi, cos
import time, sys
BASE=sys.argv[2] if len(sys.argv)>2 else 'rough'
mp.dps=int(sys.argv[3]) if len(sys.argv)>3 else 17
def omk(t,nu):
    if BASE=='smooth':
        if t==0:
            return mpf(1)
        return (2*t+1-exp(-2*t))/(sinh(2*t)+2*t)
    ka=3-4*nu
    return (2*ka*exp(-2*t)+4*t*t+4*t+1+ka*ka)/(2*ka*cosh(2*t)+4*t*t+1+ka*ka)
def I(h,nu,nth):
    h=mpf(h); nu=mpf(nu)
    tp=[mpf(i)/4 for i in range(0,161)]
    # Gauss-Legendre on theta in [0, pi/4]
    import mpmath
    xs,ws=zip(*[(x,w) for x,w in mpmath.calculus.quadrature.GaussLegendre(mp).calc_nodes(nth, mp.prec)])
    c=0
    for x,w in zip(xs,ws):
        th=(x+1)*pi/8; wt=w*pi/8
        R=1/cos(th)
        f=lambda t: omk(t,nu)*R*besselj(1,t*R/h)/t if t>0 else omk(t,nu)*R*R/(2*h)
        c+=wt*quad(f,tp,method='gauss-legendre')
    return 4/pi*(log(1+sqrt(2))-c)
t0=time.time()
h=sys.argv[1]
for nth in [3,4]:
    print(h, BASE, nth, I(h,'0.3',nth), time.time()-t0, flush=True)
