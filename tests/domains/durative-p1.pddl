(define (problem d1) (:domain dur) (:objects a - thing) (:init) (:goal (done a)))
