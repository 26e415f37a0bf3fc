# Sourced by bench scripts: survey_ecef FILE prints the "lat lon h" of a survey file (degrees,
# metres) as ECEF x,y,z on WGS 84, the form --rover-pos and --base-pos take.
survey_ecef() {
  python3 -c "
import math,sys
lat,lon,h=(float(x) for x in open(sys.argv[1]).read().split()[:3])
a=6378137.0; f=1/298.257223563; e2=f*(2-f); la,lo=math.radians(lat),math.radians(lon)
n=a/math.sqrt(1-e2*math.sin(la)**2)
print('%.4f,%.4f,%.4f'%((n+h)*math.cos(la)*math.cos(lo),(n+h)*math.cos(la)*math.sin(lo),(n*(1-e2)+h)*math.sin(la)))" "$1"
}
