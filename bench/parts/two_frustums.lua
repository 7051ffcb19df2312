-- Two cone frustums stacked on a shared rim of radius 25.
return cylinder{r1=30, r2=25, h=10} + cylinder{r1=25, r2=28, h=10}:translate(0, 0, 10)
