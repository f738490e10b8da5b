// A triangle with a square hole, off the axis, twisted a whole turn in 5
// slices (OpenSCAD's count for so small a shape): each slice turns by 72
// degrees, so the side faces fold through one another and the mesh
// crosses itself. OpenSCAD draws its triangles as they are, the folds
// included.
// camera: 12,-16,14,-1,0.5,2.4
linear_extrude(height = 4.78, twist = 360)
    translate([-2.63, 0.31])
        polygon(points = [[1.508, 0.192], [-0.698, 1.225], [-0.908, -1.256],
                          [-0.3, 0.3], [0.3, 0.3], [0.3, -0.3], [-0.3, -0.3]],
                paths = [[0, 1, 2], [3, 4, 5, 6]]);
