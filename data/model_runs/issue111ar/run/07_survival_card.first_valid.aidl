# Request (camping): a credit-card survival tool, fibre-laser cut from 0.8 mm stainless steel,
# 85.6 x 54 mm overall with 3.2 mm corner radii. Along the top edge, three open-ended hex wrench
# notches for 7, 8 and 10 mm nuts (jaws = across flats; each notch a channel as wide as the nut
# from the edge down to the nut's centre, 0.75 x the size below the edge, with the nut's lower
# half as a V bottom), centred at 24, 10 mm left of the card's centre and 6 mm right of it, each
# size engraved (2 mm) 2 mm under its notch. A 4 mm lanyard hole 6 mm in from the top and left
# edges. A bottle opener at the right end: an 18 mm round opening centred 26 mm right of and 6 mm
# above the card's centre, merged with a 6 x 12 mm lip on its right, leaving 4.8 mm of steel at
# the end. A saw edge on the left: 20 teeth, 2 mm pitch, 1 mm tall, centred on the edge (the
# 85.6 mm includes them). Along the bottom edge a 60 mm ruler, zero 8 mm from the left edge:
# ticks from the edge every mm, 1.5 mm long, 2.5 at every 5, 3.5 at every 10, numbers 0..6
# (2 mm tall) above the long ticks. "SURVIVAL CARD" engraved, 3.5 mm single stroke, its middle
# 14 mm left of the card's centre, baseline 2 mm above the centre.

thickness 0.8 mm

W = 85.6 mm
H = 54 mm
L = -W / 2                 # the teeth's tips: the card's left edge
def tick(i) = 3.5 mm if i % 10 == 0 else (2.5 mm if i % 5 == 0 else 1.5 mm)
sizes = [7 mm, 8 mm, 10 mm]
offsets = [-24 mm, -10 mm, 6 mm]

solid card {
    body = RoundedRectangle(center=(0.5, 0), width=W - 1, height=H, corner_radius=3.2)
    solid saw {
        for i in range(20) {
            tooth = Triangle((L + 1, -20 + 2 * i), (L, -19 + 2 * i), (L + 1, -18 + 2 * i))
        }
    }
    hole wrenches {
        for k in range(3) {
            jaw = Rectangle(center=(offsets[k], H / 2 - 0.75 * sizes[k] / 2 + 0.5),
                            width=sizes[k], height=0.75 * sizes[k] + 1, overrun=true)
            nut = RegularPolygon(center=(offsets[k], H / 2 - 0.75 * sizes[k]),
                                 across_flats=sizes[k], sides=6, rotation=90)
        }
    }
    hole lanyard {
        c = Circle(center=(L + 6, H / 2 - 6), diameter=4)
    }
    hole opener {
        round = Circle(center=(26, 6), diameter=18)
        lip = Rectangle(center=(35, 6), width=6, height=12)
    }
    drawing marks {
        for k in range(3) {
            size_label = Text(str(round(sizes[k] / 1 mm)),
                              (offsets[k], H / 2 - 0.75 * sizes[k] - sizes[k] / sqrt(3) - 2),
                              size=2, valign="top")
        }
        title = Text("SURVIVAL CARD", (-14, 2), size=3.5)
    }
    drawing ruler {
        for i in range(61) {
            t = Line((L + 8 + i, -H / 2), (L + 8 + i, -H / 2 + tick(i)))
        }
        for k in range(7) {
            n = Text(str(k), (L + 8 + 10 * k, -H / 2 + 4.5), size=2)
        }
    }
    Fixed(body)

    assert abs(self.bb.width - 85.6 mm) < 0.01 mm and abs(self.bb.height - 54 mm) < 0.01 mm, "85.6 x 54 overall"
    assert abs(wrenches.jaw[0].width - 7 mm) < 0.01 mm and abs(wrenches.jaw[1].width - 8 mm) < 0.01 mm and abs(wrenches.jaw[2].width - 10 mm) < 0.01 mm, "7, 8, 10 mm jaws"
    assert abs(wrenches.nut[2].center.x - body.center.x + 0.5 mm - 6 mm) < 0.01 mm, "10 mm notch 6 right of centre"
    assert abs(body.bb.top - lanyard.c.center.y - 6 mm) < 0.01 mm and abs(lanyard.c.center.x - self.bb.left - 6 mm) < 0.01 mm, "lanyard 6 in"
    assert abs(self.bb.right - opener.lip.bb.right - 4.8 mm) < 0.01 mm, "4.8 mm of steel at the end"
    assert len(saw.tooth) == 20, "20 teeth"
    assert abs(ruler.t[0].start.x - self.bb.left - 8 mm) < 0.01 mm, "zero 8 from the left edge"
    assert abs(ruler.t[60].start.x - ruler.t[0].start.x - 60 mm) < 0.01 mm, "60 mm ruler"
    assert marks.bb.bottom > ruler.bb.top + 1 mm, "title clear of the ruler"
    assert opener.bb.left > wrenches.bb.right + 3 mm or opener.bb.top < wrenches.bb.bottom - 3 mm, "opener clear of the wrenches"
}
