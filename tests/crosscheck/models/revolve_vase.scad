// A vase: a polygon profile with a hollow (outer wall, inner wall, a
// floor), revolved with $fn = 40; seen from above so the inside shows.
// camera: 40,-50,60,0,0,12
rotate_extrude($fn = 40)
    polygon(points = [[0, 0], [8, 0], [10, 4], [9, 12], [6, 18], [7, 24],
                      [6, 24], [5, 18], [8, 12], [9, 4], [7, 1.5], [0, 1.5]]);
