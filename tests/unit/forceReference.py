# interDemFoam: CFD-DEM coupling of OpenFOAM and LIGGGHTS
# Copyright (C) 2026 the interDemFoam authors
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE)
# Hand computation of the force-model reference values (independent of the C++)
import math
pi=math.pi
def sn(d,rho,mu,slip):
    Re=d*rho*slip/mu
    Cd=24/Re*(1+0.15*Re**0.687) if Re<1000 else 0.44
    return 0.5*Cd*rho*pi*d*d/4*slip*slip
def difelice(d,rho,mu,eps,slip,rong=False):
    Re=eps*d*rho*slip/mu
    Cd=(0.63+4.8/math.sqrt(Re))**2
    if rong: chi=2.65*(eps+1)-(5.3-3.5*eps)*eps**2*math.exp(-(1.5-math.log10(Re))**2/2)
    else: chi=3.7-0.65*math.exp(-(1.5-math.log10(Re))**2/2)
    return 0.5*Cd*rho*pi*d*d/4*eps**(2-chi)*slip*slip
def gidaspow(d,rho,mu,eps,slip):
    Vp=pi*d**3/6
    if eps<0.8:
        beta=150*(1-eps)**2*mu/(eps*d*d)+1.75*(1-eps)*rho*slip/d
    else:
        Re=eps*d*rho*slip/mu
        Cd=24/Re*(1+0.15*Re**0.687) if Re<1000 else 0.44
        beta=0.75*Cd*eps*(1-eps)*rho*slip/d*eps**-2.65
    return beta*Vp/(1-eps)*slip
states={'diluteLowRe':(1e-3,1000,1e-3,0.95,0.005),'denseLowRe':(1e-3,1000,1e-3,0.4,0.01),
        'denseHighRe':(5e-3,1000,1e-3,0.45,0.3),'diluteHighRe':(5e-3,1000,1e-3,0.9,0.3)}
for k,(d,rho,mu,eps,slip) in states.items():
    print(k, 'SN %.12e DF %.12e Rong %.12e Gid %.12e'%(sn(d,rho,mu,slip),difelice(d,rho,mu,eps,slip),difelice(d,rho,mu,eps,slip,True),gidaspow(d,rho,mu,eps,slip)))
# lift
d,rho,mu=1e-3,1000,1e-3; U=0.05; gamma=20.0
print('Saffman Fy %.12e'%(1.61*d*d*math.sqrt(mu*rho)*gamma**-0.5*U*gamma))
V=0.1; Om=50.0
print('Magnus Fy %.12e'%(pi/8*d**3*rho*Om*V))
# Wiberg & Smith bed lift: C_L 0.2, d 10 mm, water, grain at rest, 0.5 m/s
# over its top and 0.1 m/s under its bottom
CL,d,rho=0.2,0.01,1000.0
print('WibergSmith Fz %.12e'%(0.5*CL*rho*pi/4*d*d*(0.5**2-0.1**2)))
