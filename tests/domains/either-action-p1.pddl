(define (problem either-1) (:domain either-action) (:objects c - cup) (:init) (:goal (washed c)))
