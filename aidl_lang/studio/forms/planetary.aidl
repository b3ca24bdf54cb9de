# The studio's form of examples/generators/planetary.aidl: its arguments as params whose
# ranges follow each other (docs/studio.md, "Forms that cannot fail").
import "std/gears.aidl"

# The counts depend on each other: the ring has sun + 2 x planet teeth, and the planets sit
# evenly when 2 x (sun + planet) divides by planets, so the sun's slider runs from 8 to 48 in
# steps of planets (of half an even count), on the counts that do; and it is large enough that
# neighbouring planets clear each other's tips: (sun + planet) x sin(180 deg / planets) >
# planet + 2 (with half a tooth to spare).
param planets = 3, min = 2, max = 5, step = 1
param planet = 18, min = 12, max = 40, step = 1  # under 12 teeth its tips cut into the ring's (interference: no profile shift)
param sun = 12, min = max(8, ceil((planet * (1 - sin(180 deg / planets)) + 2.5) / sin(180 deg / planets))) + (2 * planets - (max(8, ceil((planet * (1 - sin(180 deg / planets)) + 2.5) / sin(180 deg / planets))) + planet) % (planets / (2 - planets % 2))) % (planets / (2 - planets % 2)), max = 48 - (48 + planet) % (planets / (2 - planets % 2)), step = planets / (2 - planets % 2)
param module = 2 mm, min = 0.5 mm, max = 6 mm, step = 0.25 mm
param axle = 4 mm, min = 1 mm, max = min(16 mm, module * (min(sun, planet) - 2.5) - 1.1 mm), step = 0.05 mm

thickness 3 mm

assembly reducer {
    set = planetary(sun=sun, planet=planet, ring=sun + 2 * planet, planets=planets,
                    module=module, axle=axle)
}
